"""The Elastica workbench: the Workbench class, command registration, and the GUI
side of the features (their view providers, also for documents made without the
GUI, through proxy.VIEW_HOOK)."""
import FreeCADGui as Gui

from . import ICONPATH, icon, library_problem, proxy, viewproviders


class ElasticaWorkbench(Gui.Workbench):
    """Fit sketches and scanned keylines with Euler's elastica, elastic blends,
    elliptic blending-function curves, G2 quadratic B-splines, curvature combs."""

    MenuText = "Elastica"
    ToolTip = ("Euler's elastica: fairing fits, elastic blends, elliptic blend curves, "
               "G2 quadratic B-splines, curvature combs")
    Icon = icon("elastica")

    def GetClassName(self):
        return "Gui::PythonWorkbench"

    def Initialize(self):
        from . import commands, preferences
        names = commands.register()
        self.appendToolbar("Elastica", names)
        self.appendMenu("Elastica", names)
        preferences.register()
        problem = library_problem()
        if problem:
            commands.message(problem)

    def Activated(self):
        pass

    def Deactivated(self):
        pass


proxy.VIEW_HOOK[:] = [viewproviders.attach, viewproviders.restored]
proxy.IDLE_HOOK[:] = [viewproviders.when_idle]
Gui.addIconPath(ICONPATH)
Gui.addWorkbench(ElasticaWorkbench())
