"""freecadcmd -t test of the workbench commands' tooltips as the designer reads them over a
toolbar button (QA24gui F6: the blend's spoke of a selection 'by a script, without a
click', which a designer does not make)."""
import unittest

from freecad.elastica import commands as C


class CommandTipsTest(unittest.TestCase):
    def test_no_command_tip_speaks_of_scripts(self):
        for name, command in C.COMMANDS.items():
            tip = command().GetResources()["ToolTip"]
            self.assertTrue(tip, name)
            self.assertNotIn("script", tip.lower(), name)     # main: Elastica_Blend's


if __name__ == "__main__":
    unittest.main()
