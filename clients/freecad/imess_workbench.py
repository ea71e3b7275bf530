# The IMESS workbench and its command (toolbar, menu): the capture panel. Registered with
# FreeCAD by InitGui.py when FreeCAD starts.
"""The IMESS workbench."""
import os

import FreeCAD
import FreeCADGui

IMESS_DIR = os.path.dirname(os.path.abspath(__file__))
IMESS_ICON = os.path.join(IMESS_DIR, "Resources", "IMESS.svg")


class IMESSCaptureCommand:
    def GetResources(self):  # noqa: N802 - FreeCAD's name
        return {"Pixmap": IMESS_ICON, "MenuText": "IMESS capture panel",
                "ToolTip": "Connect to messd: live probe, points as they are measured, jog, fits, inspection"}

    def Activated(self):  # noqa: N802
        import imess_panel
        imess_panel.show_panel()

    def IsActive(self):  # noqa: N802
        return True


class IMESSWorkbench(FreeCADGui.Workbench):
    MenuText = "IMESS"
    ToolTip = "Measure with an IMESS messd: live points, jog, fits, inspection plans"
    Icon = IMESS_ICON

    def Initialize(self):  # noqa: N802
        self.appendToolbar("IMESS", ["IMESS_Capture"])
        self.appendMenu("IMESS", ["IMESS_Capture"])

    def Activated(self):  # noqa: N802
        import imess_panel
        imess_panel.show_panel()

    def GetClassName(self):  # noqa: N802
        return "Gui::PythonWorkbench"


FreeCADGui.addCommand("IMESS_Capture", IMESSCaptureCommand())
FreeCADGui.addWorkbench(IMESSWorkbench())
FreeCAD.Console.PrintLog("IMESS add-on loaded from %s\n" % IMESS_DIR)
