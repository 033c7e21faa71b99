"""The Elastica workbench: the Workbench class and command registration only."""
import FreeCADGui as Gui

from . import icon


class ElasticaWorkbench(Gui.Workbench):
    """Fit sketches and scanned keylines with Euler's elastica, elastic blends,
    elliptic blending-function curves, curvature combs, B-splines back into sketches."""

    MenuText = "Elastica"
    ToolTip = "Euler's elastica: fairing fits, elastic blends, elliptic blend curves, curvature combs"
    Icon = icon("elastica")

    def GetClassName(self):
        return "Gui::PythonWorkbench"

    def Initialize(self):
        from . import commands, preferences
        names = commands.register()
        self.appendToolbar("Elastica", names)
        self.appendMenu("Elastica", names)
        preferences.register()

    def Activated(self):
        pass

    def Deactivated(self):
        pass


Gui.addWorkbench(ElasticaWorkbench())
