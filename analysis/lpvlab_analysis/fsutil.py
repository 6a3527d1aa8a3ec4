"""Atomic file writes.

A report is often regenerated while someone looks at it (or a previous run
was interrupted), so every output is written to a temporary name in the
same directory and moved into place with os.replace, which is atomic on
POSIX: a reader sees the old file or the new one, never a truncated one.
"""
import os
import tempfile


def _tmp_path(path):
    d = os.path.dirname(os.path.abspath(path))
    os.makedirs(d, exist_ok=True)
    base = os.path.basename(path)
    fd, tmp = tempfile.mkstemp(prefix="." + base + ".", suffix=".tmp" + os.path.splitext(base)[1], dir=d)
    os.close(fd)
    return tmp


def write_text(path, text):
    """Write text (UTF-8) to path atomically."""
    tmp = _tmp_path(path)
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def write_with(path, writer):
    """Call writer(tmp_path) to produce the file, then move it onto path atomically.

    The temporary name keeps the extension of path so that writers which
    pick a format from the extension (matplotlib savefig, OIIO) still work.
    """
    tmp = _tmp_path(path)
    try:
        writer(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def load_json(directory, name, required_key, what):
    """DIR/name as JSON, refused (SummaryError naming the file) when it cannot be read or lacks a
    non-empty `required_key` ("no <required_key> (not written by <what>?)")."""
    import json
    from .summary import SummaryError
    path = os.path.join(directory, name)
    try:
        with open(path) as f:
            result = json.load(f)
    except (OSError, ValueError) as exc:
        raise SummaryError(f"{path}: cannot be read ({exc})") from exc
    if not isinstance(result, dict) or not result.get(required_key):
        raise SummaryError(f"{path}: no {required_key} (not written by {what}?)")
    return result
