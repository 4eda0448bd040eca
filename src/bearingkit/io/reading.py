"""Reading input files: regular files only, at most MAX_INPUT_BYTES, UTF-8, TOML nested at most
MAX_NESTING deep. Every refusal is one :class:`~bearingkit.errors.InputError` line naming the file.

Input files come from other people (a study names a bearing file; the web app takes uploads), so
reading is bounded before anything is parsed:

- the path must name a **regular file** (``/dev/zero``, a directory, a FIFO, a socket are refused
  from ``fstat`` of the opened descriptor, opened non-blocking so a FIFO cannot stall the open);
- at most :data:`MAX_INPUT_BYTES` are read (a larger file is refused from its size, and the read
  itself stops one byte past the cap should the file grow meanwhile);
- the bytes must be UTF-8 (a leading byte-order mark is dropped);
- arrays and inline tables may nest at most :data:`MAX_NESTING` deep (checked on the text before
  ``tomllib``, whose recursive descent otherwise ends in RecursionError; the parsed tables are
  checked again, since dotted keys ``a.b.c…`` nest without brackets).

Messages quote no more of the file than a short excerpt of the line a TOML error points at.
"""

from __future__ import annotations

import json
import os
import re
import stat
import tomllib
from pathlib import Path

from bearingkit.errors import SHORT_SOURCE_CHARS, InputError, os_hint, quote, shown

#: Largest input file read [bytes]: 1 MiB. A bearing file is a few kB; 1,000 load cases (the cap
#: per file, bearingkit.io.sections.MAX_LOAD_CASES) with comments stay below 300 kB.
MAX_INPUT_BYTES = 1 << 20
#: Deepest nesting of arrays, inline tables and tables [levels]; input files use at most 4.
MAX_NESTING = 16
#: Longest excerpt of the offending line quoted in a TOML error [characters].
EXCERPT_CHARS = 40

# Strings and comments of TOML text, removed before the brackets are counted. Every alternative,
# once its opening quote matches, runs to its closing quote or to the end of the line (of the text)
# and then always matches: an unterminated string never makes the scan restart at the next quote
# (that restart was quadratic on a line of escaped quotes). Linear time.
_STRINGS_AND_COMMENTS = re.compile(
    r'"""(?:[^"\\]+|\\[\s\S]?|"(?!""))*(?:"""|\Z)'
    r"|'''(?:[^']+|'(?!''))*(?:'''|\Z)"
    r'|"(?:[^"\\\n]+|\\[^\n]?)*(?:"|$)'
    r"|'[^'\n]*(?:'|$)"
    r"|#[^\n]*",
    re.MULTILINE,
)
_TOKENS = re.compile(f"{_STRINGS_AND_COMMENTS.pattern}|(?P<bracket>[\\[\\]{{}}])", re.MULTILINE)
_POSITION = re.compile(r"\(at line (\d+), column (\d+)\)")


def read_text(path, limit: int = MAX_INPUT_BYTES) -> str:
    """The text of the input file at ``path``, read within the limits above (``limit`` bytes at most:
    :data:`MAX_INPUT_BYTES` for input files, more for the matrix files an input names).

    Raises
    ------
    InputError
        ``"PATH: …"`` when the path is not a readable regular file, is larger than
        :data:`MAX_INPUT_BYTES` or is not UTF-8.
    """
    path = Path(path)
    name = shown(path, SHORT_SOURCE_CHARS)  # the reason must fit the message after it
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        fd = os.open(path, flags)
    except FileNotFoundError:
        raise InputError(f"{name}: cannot read the file (no such file)") from None
    except IsADirectoryError:
        raise InputError(f"{name}: cannot read the file (it is a directory)") from None
    except PermissionError:
        raise InputError(f"{name}: cannot read the file (permission denied)") from None
    except ValueError:  # os.open refuses a name holding a NUL byte
        raise InputError(f"{name}: cannot read the file (its name holds a NUL byte)") from None
    except OSError as exc:
        what = (exc.strerror or type(exc).__name__).lower()
        raise InputError(f"{name}: cannot read the file ({what}{os_hint(exc.errno)})") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            kind = _kind(info.st_mode)
            raise InputError(f"{name}: cannot read the file (it is {kind}, not a regular file)")
        if info.st_size > limit:
            raise InputError(
                f"{name}: cannot read the file (it holds {_size(info.st_size)}; input files may hold at "
                f"most {_size(limit)})"
            )
        with os.fdopen(fd, "rb", closefd=False) as f:
            data = f.read(limit + 1)
    except OSError as exc:
        raise InputError(f"{name}: cannot read the file ({exc.strerror or type(exc).__name__})") from None
    finally:
        os.close(fd)
    if info.st_size == 0 and data:
        # /proc/self/environ and its kind: "regular" files of size 0 whose bytes the kernel makes up
        # as they are read. Their contents are never parsed (a TOML error would quote them).
        raise InputError(
            f"{name}: cannot read the file (it is a file the system generates, not an input file)"
        )
    if len(data) > limit:
        raise InputError(
            f"{name}: cannot read the file (it holds more than {_size(limit)}, the most an input "
            "file may hold)"
        )
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(
            f"{name}: is not UTF-8 text (byte {exc.start} cannot be decoded); input files are TOML text"
        ) from None


#: Longest name of one path component and of a whole path a data file may give [bytes] (the limits
#: of Linux, macOS and Windows file systems: a longer name is refused before the system sees it).
MAX_NAME_BYTES = 255
MAX_PATH_BYTES = 4096


def confined_path(name, base, field: str, allowed=()) -> Path:
    """The file a data file names (a study's ``bearing``, a shaft's bearing ``file``), confined.

    A data file may come from someone else, so the path it gives is checked as text and resolved
    before anything opens it (:func:`read_text` reads it afterwards):

    - a string without NUL bytes or other control characters, components of at most
      :data:`MAX_NAME_BYTES` bytes, at most :data:`MAX_PATH_BYTES` in all;
    - no ``~`` (never expanded: ``~/.bashrc`` is refused, not read);
    - relative to ``base`` (the data file's folder); with symbolic links resolved it must lie in
      ``base``, in the folder above it (a project's ``studies/`` beside its bearing files; not when
      that is the file system's root, a folder directly under it or the home folder), or in a folder
      of ``allowed`` (folders the user named on the command line, ``--allow-path``); an absolute path
      likewise;
    - no hidden file or folder (a name starting with ``.``) below that folder: ``../.ssh/config`` is
      refused even where the folder above is the home folder.

    Returns the resolved path; raises :class:`InputError` ``"FIELD (NAME): …"`` naming the rule. The
    file itself is neither opened nor read here.
    """
    q = quote(name, SHORT_SOURCE_CHARS)
    if not isinstance(name, str):
        raise InputError(f"{field} ({q}) must be a file name (text)")
    if not name.strip():
        raise InputError(f"{field} ({q}) must name a file")
    if not name.isprintable():
        raise InputError(f"{field} ({q}) holds a NUL byte or a control character; expected a file name")
    raw = name.encode("utf-8", "surrogateescape")
    if len(raw) > MAX_PATH_BYTES or any(
        len(p) > MAX_NAME_BYTES for p in raw.replace(b"\\", b"/").split(b"/")
    ):
        raise InputError(
            f"{field} ({q}) is too long a file name: at most {MAX_NAME_BYTES} bytes per folder or "
            f"file name and {MAX_PATH_BYTES} in all"
        )
    if name.startswith("~"):
        raise InputError(
            f"{field} ({q}): '~' is not expanded in a file; give the path relative to this file's folder"
        )
    base = Path(os.path.realpath(base))
    roots = [base, *(Path(os.path.realpath(a)) for a in allowed)]
    if _project_folder(base.parent):
        roots.append(base.parent)
    try:
        target = Path(os.path.realpath(base / name))  # an absolute name replaces base
    except (OSError, ValueError):
        raise InputError(f"{field} ({q}): the system cannot resolve this path") from None
    root = next((r for r in roots if target == r or r in target.parents), None)
    if root is None:
        raise InputError(
            f"{field} ({q}) lies outside this file's folder (and its project's folder above it); a "
            "data file may name only files there, or in a folder given with --allow-path on the command line"
        )
    hidden = [p for p in target.relative_to(root).parts if p.startswith(".")]
    if hidden:
        raise InputError(
            f"{field} ({q}) names a hidden file or folder ({quote(hidden[0])}); a data file may not"
        )
    return target


def _project_folder(folder: Path) -> bool:
    """Whether the folder above a data file's may be reached from it: not the file system's root, a
    folder directly under it (``/tmp``, ``/home``) or the home folder (``~/Downloads/x.toml`` must not
    reach the rest of ``~``)."""
    try:
        home = Path(os.path.realpath(Path.home()))
    except (RuntimeError, KeyError, OSError):  # no home folder known
        home = None
    return len(folder.parts) > 2 and folder != home


def parse_toml(text: str, source: str) -> dict:
    """Parse TOML text (nesting checked before and after ``tomllib``); InputError naming ``source``."""
    if len(text) > MAX_INPUT_BYTES:  # text handed over directly (loads), not read from a file
        raise InputError(
            f"{source}: is {len(text)} characters; input files may hold at most {MAX_INPUT_BYTES}"
        )
    depth, line = _bracket_depth(text)
    if depth > MAX_NESTING:
        raise InputError(
            f"{source}: line {line}: arrays or inline tables nested more than {MAX_NESTING} deep; "
            "input files need at most 4 levels"
        )
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(
            f"{source}: not valid TOML ({_toml_message(str(exc), text)}){_json_hint(text)}"
        ) from None
    except ValueError as exc:  # tomllib's int() of a number of more than 4,300 digits
        what = "a number of more than 4300 digits" if "digits" in str(exc) else "a value it cannot read"
        raise InputError(f"{source}: not valid TOML ({what})") from None
    except RecursionError:  # the pre-scan above should make this unreachable; the backstop stays
        raise InputError(f"{source}: not valid TOML (nested too deeply)") from None
    if table_depth(data) > MAX_NESTING:
        raise InputError(
            f"{source}: tables nested more than {MAX_NESTING} deep (dotted keys); input files need at "
            "most 4 levels"
        )
    return data


def load_toml(path) -> dict:
    """:func:`read_text` then :func:`parse_toml`, errors naming the path."""
    return parse_toml(read_text(path), str(path))


def table_depth(data) -> int:
    """Nesting depth of dicts and lists (0 for a scalar), computed without recursion."""
    deepest = 0
    stack = [(data, 0)]
    while stack:
        node, level = stack.pop()
        if isinstance(node, dict):
            children = node.values()
        elif isinstance(node, list):
            children = node
        else:
            continue
        deepest = max(deepest, level + 1)
        if deepest > MAX_NESTING:
            return deepest
        stack.extend((child, level + 1) for child in children)
    return deepest


def _bracket_depth(text: str) -> tuple[int, int]:
    """(deepest nesting of [ and { outside strings and comments, line where it first passes the cap)."""
    depth = deepest = 0
    for match in _TOKENS.finditer(text):
        ch = match.group("bracket")
        if ch is None:  # a string or a comment: skipped whole
            continue
        if ch in "[{":
            depth += 1
            if depth > deepest:
                deepest = depth
                if deepest > MAX_NESTING:
                    return deepest, text.count("\n", 0, match.start()) + 1
        else:
            depth = max(depth - 1, 0)
    return deepest, text.count("\n") + 1


def _toml_message(message: str, text: str) -> str:
    """tomllib's message (cut short: it may name keys) with a short excerpt of the line it points at."""
    match = _POSITION.search(message)
    core = message[: match.start()].rstrip() if match else message
    core = core if len(core) <= 100 else core[:99] + "…"
    if match is None:
        return core
    lines = text.splitlines()
    number = int(match.group(1))
    where = match.group().strip("()")
    if 1 <= number <= len(lines) and lines[number - 1].strip():
        return f"{core}, {where}: {quote(lines[number - 1].strip(), EXCERPT_CHARS)}"
    return f"{core}, {where}"


def _json_hint(text: str) -> str:
    """``"; the file looks like JSON …"`` when the text parses as a JSON object, else ``""``."""
    if not text.lstrip().startswith("{"):
        return ""
    try:
        looks = isinstance(json.loads(text), dict)
    except (ValueError, RecursionError):
        looks = text.lstrip().startswith('{"')
    if not looks:
        return ""
    return (
        "; the file looks like JSON: bearingkit reads TOML ([bearing], [geometry] … sections with "
        "key = value lines; see docs/input-format.md)"
    )


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISFIFO(mode):
        return "a pipe (FIFO)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a special file"


def _size(n: int) -> str:
    if n >= 1 << 20:
        return f"{n / (1 << 20):.3g} MiB"
    if n >= 1 << 10:
        return f"{n / (1 << 10):.3g} KiB"
    return f"{n} bytes"
