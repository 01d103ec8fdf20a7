#!/usr/bin/env python3
"""No include cycles: between two modules, or between two folders.

A module is a header and its source (renderer/image.h and image.cpp): a
source that includes the header of a module whose header or source includes
its own header is a cycle, though no file includes itself. A folder holds
its subfolders, so renderer/ and renderer/gpu/ may include each other; two
folders neither of which holds the other (renderer/ and image/,
tools/common/ and tools/sfrender/) may not both include the other. A test
(*_test.cpp) counts for its module but not for its folder: a test may take
its support from any folder without making the code's folders depend.

Reads every #include "..." and #include <...> of the sources under
SOURCE_DIRS that names a file of the tree (found beside the includer, at the
tree's root or under include/); system and generated headers are left out.

    include_cycles.py SOURCE_DIR
"""

import os
import re
import sys

SOURCE_DIRS = ["include", "libscene", "renderer", "image", "tools", "python/src", "bench",
               "examples"]
EXTENSIONS = (".h", ".hpp", ".cpp", ".cc", ".def", ".inc")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def sources(root):
    for top in SOURCE_DIRS:
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if name.endswith(EXTENSIONS):
                    yield os.path.relpath(os.path.join(folder, name), root)


def resolve(root, includer, target):
    for base in (os.path.dirname(includer), "", "include"):
        path = os.path.normpath(os.path.join(base, target))
        if os.path.isfile(os.path.join(root, path)):
            return path
    return None


def module(path):
    return os.path.splitext(path)[0]


def holds(outer, inner):
    return inner == outer or inner.startswith(outer + "/")


def cycles(edges):
    """The strongly connected components of more than one node (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    for start in sorted(edges):
        if start in index:
            continue
        # Iterative, so that a deep include chain does not meet the
        # recursion limit.
        work = [(start, iter(sorted(edges[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            advanced = False
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(edges.get(successor, ())))))
                    advanced = True
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    module_edges, folder_edges, why = {}, {}, {}
    count = 0
    for path in sources(root):
        count += 1
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for target in INCLUDE.findall(text):
            included = resolve(root, path, target)
            if not included:
                continue
            a, b = module(path), module(included)
            if a != b:
                module_edges.setdefault(a, set()).add(b)
                why.setdefault((a, b), f"{path} includes {included}")
            fa, fb = os.path.dirname(path), os.path.dirname(included)
            if not path.endswith("_test.cpp") and not holds(fa, fb) and not holds(fb, fa):
                folder_edges.setdefault(fa, set()).add(fb)
                why.setdefault((fa, fb), f"{path} includes {included}")

    failures = 0
    for kind, edges in (("modules", module_edges), ("folders", folder_edges)):
        for component in cycles(edges):
            failures += 1
            print(f"FAIL: an include cycle between {kind} {', '.join(component)}:",
                  file=sys.stderr)
            members = set(component)
            for a in component:
                for b in sorted(edges.get(a, ())):
                    if b in members:
                        print(f"  {why[(a, b)]}", file=sys.stderr)
    if failures:
        sys.exit(1)
    print(f"PASS: no include cycle between the modules or the folders of {count} sources")


if __name__ == "__main__":
    main()
