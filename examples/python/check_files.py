#!/usr/bin/env python3
"""sfcheck in a few lines: every diagnostic of every file named, and a
summary; exits 1 when any file has an error.

    python3 check_files.py [OUTPUT_FOLDER] FILE...

(OUTPUT_FOLDER is unused: the examples' tests pass one to each.) With no
FILE, the scenes bundled in examples/ are checked.
"""

import glob
import os
import sys

import scenefile

HERE = os.path.dirname(os.path.abspath(__file__))


def main() -> int:
    files = sys.argv[2:] or sorted(glob.glob(os.path.join(HERE, "..", "*.sf")) +
                                   glob.glob(os.path.join(HERE, "..", "*.txt")))
    errors = warnings = 0
    for path in files:
        try:
            diagnostics = scenefile.check(path)
        except OSError as e:
            print(f"{path}: error: cannot read the file: {e.strerror}")
            errors += 1
            continue
        for d in diagnostics:
            print(d)
            if d.hint:
                print(f"  hint: {d.hint}")
        errors += sum(d.severity is scenefile.Severity.ERROR for d in diagnostics)
        warnings += sum(d.severity is scenefile.Severity.WARNING for d in diagnostics)
    print(f"{len(files)} files checked, {errors} errors, {warnings} warnings")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
