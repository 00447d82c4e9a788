"""Shared by the plotting scripts (run as `python3 scripts/<name>.py`, so this folder is on sys.path)."""
import importlib
import os
import sys


def require_plotting(*modules):
    """Imports the modules and selects matplotlib's file-only backend. If one is missing, e.g. under a
    pyenv python3 in PATH that does not see Debian's packages, re-runs the script once with
    /usr/bin/python3; else exits naming the packages to install."""
    try:
        for module in modules:
            importlib.import_module(module)
    except ImportError:
        if os.path.exists("/usr/bin/python3") and not os.environ.get("PIEZOCONTACT_PLOT_REEXEC"):
            os.environ["PIEZOCONTACT_PLOT_REEXEC"] = "1"
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        sys.exit("error: %s needed (apt-get install %s)"
                 % (" and ".join(modules) + (" are" if len(modules) > 1 else " is"),
                    " ".join("python3-" + m for m in modules)))
    import matplotlib
    matplotlib.use("Agg")
