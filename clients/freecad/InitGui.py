# The IMESS add-on's GUI part: FreeCAD runs this file at start for every folder in its Mod
# directories (this folder is on sys.path then). imess_workbench adds the workbench "IMESS"
# (toolbar and menu: the capture panel), which opens the panel when chosen.
import imess_workbench  # noqa: F401 - registers the workbench and its command
