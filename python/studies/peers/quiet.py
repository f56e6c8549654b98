"""Silence C-level console output (MoorDyn writes to the process's stdout and stderr directly,
past Python's sys.stdout): the file descriptors 1 and 2 go to /dev/null inside the block."""

from __future__ import annotations

import os
import sys


class Quiet:
    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = (os.dup(1), os.dup(2))
        self.null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(self.null, 1)
        os.dup2(self.null, 2)
        return self

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(self.saved[0], 1)
        os.dup2(self.saved[1], 2)
        os.close(self.null)
        for fd in self.saved:
            os.close(fd)
