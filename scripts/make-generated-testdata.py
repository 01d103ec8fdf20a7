#!/usr/bin/env python3
"""Writes the files of testdata/ that are easier to generate than to type.

Run from anywhere; the output is deterministic, so running it again gives the
same bytes. Each file's expected diagnostics sit beside it (NAME.expect).
"""
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "testdata"

CAMERA = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 1\n0 0 1 8\n0 0 0 1\n"
LIGHT = "LIGHT\n1 1 1\n1 0 0 5\n0 1 0 5\n0 0 1 5\n0 0 0 1\n"
IDENTITY = "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"


def write(relative: str, data: bytes) -> None:
    path = ROOT / relative
    path.write_bytes(data)
    assert len(data) < 100_000, path


def main() -> None:
    # A colour component of 10,000 digits that reads as an ordinary number.
    write("valid/long-number-10000-digits.sf",
          (CAMERA + LIGHT + "SPHERE\n0." + "5" * 9998 + " 1 1\n" + IDENTITY).encode())
    # A 10,000-digit integer: far above the largest double.
    write("invalid/number-10000-digits.sf",
          (CAMERA + LIGHT + "SPHERE\n1 0 0\n1 0 0 " + "9" * 10000
           + "\n0 1 0 0\n0 0 1 0\n0 0 0 1\n").encode())
    # 400 bytes of garbage from a fixed linear congruential generator.
    x = 12345
    garbage = bytearray()
    for _ in range(400):
        x = (1103515245 * x + 12345) & 0x7FFFFFFF
        garbage.append((x >> 16) & 0xFF)
    write("invalid/binary-garbage.sf", bytes(garbage))
    # More errors than sfcheck keeps (1000): it must stop and say so once.
    write("invalid/too-many-errors.txt",
          ("OUTPUT_FILE out.ppm\n" + "END LIGHT\n" * 1100).encode())


if __name__ == "__main__":
    main()
