"""``python -m agents.lqr`` = ``laddermill lqr``: the same command line, bad input reported as one line (exit
status 2)."""

import sys

from laddermill_gym.cli import main

if __name__ == "__main__":
    sys.exit(main(["lqr", *sys.argv[1:]]))
