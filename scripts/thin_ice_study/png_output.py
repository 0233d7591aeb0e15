"""Where the scripts here write a plot: the path is checked before any work (it must end in .png
and lie in a folder that exists; otherwise one message naming the flag and the value), and the
picture is written beside the old one and renamed over it, so that a failure while drawing or
writing leaves the old picture whole and no partial file behind."""
import os
import sys


def check_png_path(tool, flag, path):
    """Ends the script (exit status 2) with one message when `path` cannot take a PNG."""
    folder = os.path.dirname(os.path.abspath(path))
    if not path.lower().endswith(".png"):
        print(f"{tool}: {flag} {path} is invalid; allowed: a file name ending in .png", file=sys.stderr)
        sys.exit(2)
    if not os.path.isdir(folder):
        print(f"{tool}: {flag} {path} is invalid: there is no folder {folder}; allowed: a path in an existing folder",
              file=sys.stderr)
        sys.exit(2)


def save_png(fig, path, **savefig_options):
    """fig.savefig to PATH.partial.png, then renamed over `path`."""
    partial = (path[:-4] if path.lower().endswith(".png") else path) + ".partial.png"
    try:
        fig.savefig(partial, **savefig_options)
    except BaseException:
        if os.path.exists(partial):
            os.remove(partial)
        raise
    os.replace(partial, path)
