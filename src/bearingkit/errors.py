"""Exception types shared by every layer, and the quoting of values in their messages.

An :class:`InputError` message is one line a person reads: whatever builds it, the message is
collapsed to one line and held to :data:`MAX_MESSAGE_CHARS` (a value echoed back whole once made a
12 MB message). Values are quoted with :func:`quote`, which shortens long strings and arrays.
"""

from __future__ import annotations

import difflib

#: Longest InputError message [characters]; a longer one keeps its head and tail around " … ".
MAX_MESSAGE_CHARS = 300
#: Longest quoted string value [characters] (:func:`quote`).
MAX_QUOTED_CHARS = 40
#: Items of a list shown before " … N items" (:func:`quote`).
MAX_QUOTED_ITEMS = 3
#: Longest file name or designation shown in a message [characters] (:func:`shown`): a long path
#: still shows whole; a 10,240-character designation used to be echoed whole in front of its error.
MAX_SOURCE_CHARS = 200
#: A file name inside a message that must keep its reason within :data:`MAX_MESSAGE_CHARS`
#: (``PATH: cannot read the file (…)``) [characters].
SHORT_SOURCE_CHARS = 120


def one_line(message: str, limit: int = MAX_MESSAGE_CHARS) -> str:
    """``message`` on one line (runs of whitespace → one space) and at most ``limit`` characters.

    A longer message keeps its first two thirds and its end (where the expectation usually is).
    """
    text = " ".join(str(message).split())
    if len(text) <= limit:
        return text
    tail = limit // 3
    head = limit - tail - 3
    return f"{text[:head].rstrip()} … {text[-tail:].lstrip()}"


def shown(source, limit: int = MAX_SOURCE_CHARS) -> str:
    """A file name or designation as a message shows it: printable, at most ``limit`` characters.

    Control characters (a NUL byte, a line break in a name) become ``?``; a longer name keeps its
    head and its end (where the file name is) around ``…``.

    >>> shown("a" * 200, 20)
    'aaaaaaaaaa…aaaaaaaaa'
    """
    text = "".join(c if c.isprintable() else "?" for c in str(source))
    if len(text) <= limit:
        return text
    head = (limit - 1) // 2 + (limit - 1) % 2
    return f"{text[:head]}…{text[len(text) - (limit - 1 - head) :]}"


def error_line(message, source=None) -> str:
    """The ``error: …`` line every face prints for a refusal: one line, bounded.

    ``source`` (the file or designation the command was given) heads the line, shown by
    :func:`shown`, unless the message already names it; the rest is held to
    :data:`MAX_MESSAGE_CHARS` by :func:`one_line`. The whole line is at most about 390 characters,
    whatever the input (the one message builder of the command line, the study runner and the app).
    """
    text = _printable(" ".join(str(message).split()))
    if source is None:
        return f"error: {one_line(text)}"
    rest = text
    for name in (_printable(" ".join(str(source).split())), shown(source), shown(source, SHORT_SOURCE_CHARS)):
        if rest.startswith(f"{name}:"):  # the message names the source already
            rest = rest[len(name) + 1 :].lstrip()
            break
    return f"error: {shown(source)}: {one_line(rest)}"


def _printable(text: str) -> str:
    return text if text.isprintable() else "".join(c if c.isprintable() else "?" for c in text)


def os_error_text(exc: OSError) -> str:
    """An operating-system error in words: the path it names (shortened) and the system's reason.

    ``[Errno 28] No space left on device: '/tmp/x'`` becomes ``cannot write /tmp/x: the disk is full
    (no space left on device); free some space or choose another folder``.
    """
    where = f" {shown(exc.filename)}" if getattr(exc, "filename", None) is not None else ""
    return f"cannot use{where}: {os_reason(exc)}"


def os_reason(exc: Exception) -> str:
    """Why the system refused, in words, with what to do: ``the disk is full (no space left on device);
    free some space or choose another folder``."""
    import errno

    code = getattr(exc, "errno", None)
    reason = (getattr(exc, "strerror", None) or str(exc) or type(exc).__name__).lower()
    if code in (errno.ENOSPC, errno.EDQUOT):
        reason = f"the disk is full ({reason})"
    return f"{reason}{os_hint(code)}"


#: What to do about the operating-system errors a user meets (keyed by errno).
_OS_HINTS = {
    28: "; free some space or choose another folder",  # ENOSPC
    122: "; free some space or choose another folder",  # EDQUOT
    36: "; a file name may hold at most 255 bytes: choose a shorter one",  # ENAMETOOLONG
    13: "; choose a folder you may write to",  # EACCES
    30: "; choose a folder you may write to",  # EROFS
}


def os_hint(code) -> str:
    """``"; free some space …"``: what to do about an operating-system error (its errno), or ``""``."""
    return _OS_HINTS.get(code, "")


def quote(value, limit: int = MAX_QUOTED_CHARS) -> str:
    """A short, one-line representation of an input value for a message.

    Strings are ``repr``'d and cut after ``limit`` characters (``'aaaa…' (100000 characters)``);
    lists show their first :data:`MAX_QUOTED_ITEMS` items (``[13, 13, 13, … 100000 items]``);
    tables are named by their size. Nesting is followed two levels deep only.

    >>> quote([13] * 100000)
    '[13, 13, 13, … 100000 items]'
    """
    return _quote(value, limit, depth=2)


def _quote(value, limit: int, depth: int) -> str:
    if isinstance(value, str):
        if len(value) <= limit:
            return repr(value)
        return f"{value[:limit]!r}… ({len(value)} characters)"
    if isinstance(value, dict):
        return f"a table of {len(value)} key{'s' if len(value) != 1 else ''}"
    if isinstance(value, (list, tuple)):
        if depth <= 0:
            return f"[… {len(value)} items]"
        shown = [_quote(v, limit // 2, depth - 1) for v in value[:MAX_QUOTED_ITEMS]]
        more = f", … {len(value)} items" if len(value) > MAX_QUOTED_ITEMS else ""
        return f"[{', '.join(shown)}{more}]"
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 3 * limit:
        # no repr: Python refuses to print integers of more than 4300 digits
        return f"an integer of about {round(value.bit_length() * 0.30103)} digits"
    if isinstance(value, (bool, int, float)) or value is None:
        text = repr(value)
        return text if len(text) <= limit else f"{text[:limit]}… ({len(text)} digits)"
    return f"a {type(value).__name__}"


def nearest(name, choices, n: int = 1) -> list[str]:
    """The ``n`` choices closest to ``name`` (difflib ratio ≥ 0.6; case-insensitive equality first)."""
    if not isinstance(name, str) or len(name) > 100:
        return []
    choices = [str(c) for c in choices]
    same = [c for c in choices if c.lower() == name.lower() and c != name]
    lowered = {c.lower(): c for c in choices}
    close = [lowered[c] for c in difflib.get_close_matches(name.lower(), list(lowered), n=n, cutoff=0.6)]
    return list(dict.fromkeys(same + close))[:n]


def did_you_mean(name, choices) -> str:
    """``"; did you mean 'pitch_diameter'?"`` for the nearest choice, or ``""`` when none is near."""
    near = nearest(name, choices)
    return f"; did you mean {near[0]!r}?" if near else ""


class InputError(ValueError):
    """Bad input: one line naming the field, the value and what was expected (see :func:`one_line`)."""

    def __init__(self, message: str = ""):
        super().__init__(one_line(message))


class ConvergenceError(RuntimeError):
    """A single interactive solve that did not converge; ``result`` carries the diagnostics."""

    def __init__(self, message: str, result=None):
        super().__init__(message)
        self.result = result


class RunInterrupted(RuntimeError):
    """A long run stopped by its environment, not by its input or a bug: a worker process killed (by
    a person, or the system when out of memory) or a full disk. What was finished is kept; the
    message (one line) says what happened and how to continue (``--resume``). The command line exits
    with :data:`RUN_INTERRUPTED_EXIT`."""

    def __init__(self, message: str = ""):
        super().__init__(one_line(message))


#: Exit code of a run that stopped part-way and can be resumed (sysexits.h EX_TEMPFAIL: try again).
RUN_INTERRUPTED_EXIT = 75
