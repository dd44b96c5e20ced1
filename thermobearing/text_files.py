"""Text files users write or export: which encoding to read them in.

One job: the encoding of a scene's TOML files (scene, bearing, lubricant) and of the CSV
files a scene or a command reads (schedule protocols, rig thermocouple files, vibration
records). Editors and spreadsheets save text as UTF-8 with or without a byte-order mark
(Windows Notepad before 2019 wrote the mark), as UTF-16 with a mark (Excel's "Unicode
text", Notepad's "Unicode"), or in the Windows ANSI code page (data loggers writing
``°C``). TOML files must be UTF-8 (TOML 1.0, "Spec": "A TOML file must be a valid UTF-8
encoded Unicode document"); a UTF-16 file with its mark is read as the same text, any
other bytes are an error that says where the first one is.
"""

from __future__ import annotations

import codecs
import tomllib
from pathlib import Path

__all__ = ["text_encoding", "toml_text", "toml_text_of"]

#: byte-order marks and the codec that reads the text after them
_BOMS = ((codecs.BOM_UTF8, "utf-8-sig"), (codecs.BOM_UTF16_LE, "utf-16"),
         (codecs.BOM_UTF16_BE, "utf-16"))


def _marked(data: bytes) -> str | None:
    return next((enc for bom, enc in _BOMS if data.startswith(bom)), None)


def text_encoding(path: str | Path, fallback: str = "cp1252") -> str:
    """The codec of a CSV / text file: the one its byte-order mark names (UTF-8, UTF-16),
    else UTF-8 when every byte decodes as UTF-8, else ``fallback`` (Windows-1252: a logger
    on Windows writing ``°C`` in the ANSI code page). Read with ``errors="replace"`` when
    the fallback is used (five bytes are undefined in Windows-1252)."""
    data = Path(path).read_bytes()
    marked = _marked(data)
    if marked:
        return marked
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return fallback
    return "utf-8-sig"


def toml_text(path: str | Path) -> str:
    """The text of a TOML file: UTF-8 (a byte-order mark skipped) or UTF-16 with its mark.

    Raises ``tomllib.TOMLDecodeError`` naming the line and column of the first byte that is
    not UTF-8 (a file saved as Windows-1252 / Latin-1: ``°C`` is byte 0xB0 there), which
    the callers report as invalid TOML of their field, as they do a syntax error."""
    return toml_text_of(Path(path).read_bytes())


def toml_text_of(data: bytes) -> str:
    """The text of a TOML file's bytes ``data``, as :func:`toml_text` (same errors)."""
    marked = _marked(data)
    if marked:
        try:
            return data.decode(marked)
        except UnicodeDecodeError as exc:  # a UTF-16 mark before an odd number of bytes
            raise tomllib.TOMLDecodeError(f"not {marked.upper()} text after its byte-order "
                                          f"mark ({exc.reason})") from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        head = data[:exc.start]
        line = head.count(b"\n") + 1
        col = exc.start - (head.rfind(b"\n") + 1) + 1
        raise tomllib.TOMLDecodeError(
            f"not UTF-8 text: byte 0x{data[exc.start]:02X} at line {line}, column {col}; "
            "TOML files are UTF-8 (a file saved as Windows-1252 / Latin-1 writes the "
            "degree sign as 0xB0): save it as UTF-8") from None
