"""Strict command-line input: plain-decimal numbers and bounded reading and writing of the files
an option names (the ``aerostat`` CLI and ``aerostat simulate``).

Numbers on the command line are plain ASCII decimals (:func:`decimal`, :func:`whole`): ``1_0``,
full-width or Arabic-Indic digits, ``inf`` and ``nan`` are refused, where Python's ``float()``
reads ``1_0`` and ``１０`` as 10. A file an option names is read only when it is a regular file
and at most a given size (:func:`read_capped`), and written without ever blocking on a FIFO or
hiding a full disk (:func:`write_output`); every failure is an :class:`OptionError` naming the
option, which the CLI prints as one line.
"""

from __future__ import annotations

import argparse
import fcntl
import math
import os
import re
import stat
from pathlib import Path

#: Longest number text read from the command line [characters].
MAX_NUMBER_CHARS = 40
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]{1,3})?")
_WHOLE = re.compile(r"[+-]?[0-9]{1,18}")


def decimal(text: str) -> float:
    """A plain decimal number from the command line: ASCII digits, an optional sign, point and
    exponent; finite.

    >>> decimal("10"), decimal("-2.5e1"), decimal(".5")
    (10.0, -25.0, 0.5)
    >>> decimal("1_0")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: '1_0' is not a plain decimal number (digits 0-9, optional sign, point and exponent)
    >>> decimal("\\uff11\\uff10")  # full-width digits
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: '１０' is not a plain decimal number (digits 0-9, optional sign, point and exponent)
    """
    t = text.strip()
    if len(t) > MAX_NUMBER_CHARS or not _DECIMAL.fullmatch(t):
        raise argparse.ArgumentTypeError(
            f"{_shown(text)} is not a plain decimal number (digits 0-9, optional sign, point "
            "and exponent)"
        )
    v = float(t)
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"{_shown(text)} is not a finite number")
    return v


def whole(text: str) -> int:
    """A whole number from the command line: ASCII digits and an optional sign.

    >>> whole("12")
    12
    >>> whole("12.0")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: '12.0' is not a whole number (digits 0-9, optional sign)
    """
    t = text.strip()
    if not _WHOLE.fullmatch(t):
        raise argparse.ArgumentTypeError(
            f"{_shown(text)} is not a whole number (digits 0-9, optional sign)"
        )
    return int(t)


def _shown(text: str) -> str:
    return repr(text if len(text) <= MAX_NUMBER_CHARS else text[: MAX_NUMBER_CHARS - 3] + "...")


class OptionError(ValueError):
    """A bad command-line value: the message starts with the option (``--payload: ...``)."""

    def __init__(self, option: str, message: str) -> None:
        super().__init__(f"{option}: {message}")
        self.option = option


def read_capped(path: Path, cap: int, option: str, hint: str = "") -> bytes:
    """Read at most ``cap`` bytes of a regular file named by a CLI ``option`` (``/dev/zero``, a
    FIFO or a directory is refused); ``ValueError`` naming the option otherwise."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise OptionError(option, f"{path}: {exc.strerror or exc}") from None
    try:
        regular = stat.S_ISREG(os.fstat(fd).st_mode)
    except OSError:
        regular = False
    if not regular:  # checked on the descriptor: a directory cannot even be wrapped as a file
        os.close(fd)
        raise OptionError(option, f"{path}: not a regular file")
    with os.fdopen(fd, "rb") as fh:
        try:
            data = fh.read(cap + 1)
        except OSError as exc:
            raise OptionError(option, f"{path}: {exc.strerror or exc}") from None
    if len(data) > cap:
        raise OptionError(option, f"{path}: larger than {cap} bytes{hint}")
    return data


def write_output(option: str, path: Path, data: bytes | str) -> None:
    """Write ``data`` (text as UTF-8) to the file named by a CLI ``option``; any failure (a
    directory, no permission, a full disk such as ``/dev/full``, a FIFO without a reader) is an
    :class:`OptionError` naming the option and the path, never a traceback."""
    raw = data.encode("utf-8") if isinstance(data, str) else data
    try:
        # non-blocking open: a FIFO without a reader fails at once instead of hanging
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NONBLOCK, 0o666)
    except OSError as exc:
        raise OptionError(option, f"{path}: {exc.strerror or exc}") from None
    try:
        flags = fcntl.fcntl(fd, fcntl.F_GETFL)
        fcntl.fcntl(fd, fcntl.F_SETFL, flags & ~os.O_NONBLOCK)
        view = memoryview(raw)
        while view:
            view = view[os.write(fd, view):]
    except OSError as exc:
        raise OptionError(option, f"{path}: {exc.strerror or exc}") from None
    finally:
        try:
            os.close(fd)
        except OSError:
            pass
