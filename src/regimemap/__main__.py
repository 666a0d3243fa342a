"""``python -m regimemap``: the command line (as the ``regimemap`` console script)."""

from regimemap.cli import console_main

if __name__ == "__main__":
    console_main()
