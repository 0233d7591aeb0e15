"""How the tools refuse bad input: one line naming the tool and what is wrong, on stderr, and exit
status 2, before anything is written."""
import sys


def refuse(prog, message, status=2):
    print(f"{prog}: {message}", file=sys.stderr)
    sys.exit(status)
