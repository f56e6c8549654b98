"""A dependency-free text progress bar for scripts (stderr, one line, redrawn in place).

When stderr is not a terminal (CI logs) it prints a new line every 10 % instead of redrawing.
"""

from __future__ import annotations

import sys
import time


class ProgressBar:
    def __init__(self, total: float, label: str = "", width: int = 40, stream=None):
        self.total = float(total) if total > 0 else 1.0
        self.label = label
        self.width = width
        self.stream = stream if stream is not None else sys.stderr
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = time.perf_counter()
        self._last_decile = -1
        self._last_draw = 0.0

    def update(self, value: float, extra: str = "") -> None:
        frac = min(1.0, max(0.0, value / self.total))
        now = time.perf_counter()
        if self.tty:
            if frac < 1.0 and now - self._last_draw < 0.05:
                return
            self._last_draw = now
            filled = int(round(frac * self.width))
            bar = "#" * filled + "-" * (self.width - filled)
            self.stream.write(f"\r{self.label} [{bar}] {100 * frac:5.1f}% {extra}   ")
            self.stream.flush()
        else:
            decile = int(frac * 10)
            if decile != self._last_decile:
                self._last_decile = decile
                self.stream.write(f"{self.label} {100 * frac:5.1f}% {extra}\n")
                self.stream.flush()

    def close(self, message: str = "") -> None:
        elapsed = time.perf_counter() - self.start
        if self.tty:
            self.stream.write("\n")
        if message:
            self.stream.write(f"{message} ({elapsed:.1f} s wall)\n")
        self.stream.flush()
