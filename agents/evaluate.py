"""``python -m agents.evaluate`` = ``laddermill evaluate``: the same command line, bad input reported as one line (exit
status 2)."""

import sys

from laddermill_gym.cli import main

if __name__ == "__main__":
    sys.exit(main(["evaluate", *sys.argv[1:]]))
