#!/usr/bin/env python3
"""Checks the shape of the C++ sources (issue 24): no file over --max-file lines, no function over
--max-function lines, and no #include from a lower layer of src/ to a higher one.

    python3 scripts/check_structure.py [--max-file 600] [--max-function 120] [--list] PATH...
    python3 scripts/check_structure.py --self-test

PATH is a folder (every .cpp and .hpp in it, recursively) or a file; --exclude PATH leaves one
out. A function's length counts from the first line of its signature to its closing brace, the
lines of lambdas and local classes inside it included. Prints one line per finding (file:line,
what, how long, the limit) and exits 1 when there is any; --list prints every function over
--report lines (default 80) as well, longest first, without failing on them. --self-test
checks the counter on made-up files (a function of 121 lines found, one of 120 not, a class's
inline methods and a lambda counted with their function, an include upwards found).
"""
import argparse
import os
import re
import sys

# Lower to higher; a folder may include from its own layer and the layers before it.
LAYERS = [
    ["core"],
    ["contact", "hysteresis"],
    ["structure"],
    ["io"],
    ["sampling"],
    ["motion"],
    ["ground"],
    ["solver"],
    ["simulation"],
    ["sears"],
    ["study"],
    ["campaign"],
    ["fragility"],
    ["risk"],
    ["app"],
]
LAYER_OF = {folder: i for i, group in enumerate(LAYERS) for folder in group}

CONTAINER = re.compile(r"^(?:template\s*<[^{]*>\s*)?(?:namespace\b|class\b|struct\b|union\b|enum\b|extern\s+\"C\")")
FUNCTION_END = re.compile(
    r"\)\s*(?:const\b|noexcept\b|override\b|final\b|mutable\b|&|\s)*(?:->\s*[\w:<>,\s*&]+)?$")
INIT_LIST = re.compile(r"\)\s*(?:noexcept\s*)?:\s*[\w:]+\s*[({]")


def strip(text):
    """The text with comments, string and character literals blanked (line breaks kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, last line) of every function body in the file."""
    text = strip(open(path, encoding="utf-8").read())
    text = re.sub(r"^[ \t]*#.*$", lambda m: " " * len(m.group(0)), text, flags=re.M)
    found = []
    # Each scope: (kind, start index of its header text, line of the header).
    stack = [("container", 0)]
    header_start = 0
    line = 1
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        if stack[-1][0] != "container":
            if c == "{":
                stack.append(("block", i))
            elif c == "}":
                kind, info = stack.pop()
                if kind == "function":
                    name, first = info
                    found.append((name, first, line))
                if stack[-1][0] == "container" and kind != "member-init":
                    header_start = i + 1
            continue
        if c in ";":
            header_start = i + 1
        elif c == "}":
            stack.pop()
            header_start = i + 1
        elif c == "{":
            header = text[header_start:i]
            # Access labels (public:) belong to no declaration.
            lead = re.match(r"\s*(?:(?:public|private|protected)\s*:\s*)*", header).end()
            stripped = " ".join(header[lead:].split())
            if CONTAINER.match(stripped) and "(" not in stripped.split("{")[0].split(":")[0]:
                stack.append(("container", i))
                header_start = i + 1
            elif INIT_LIST.search(stripped) and re.search(r"[\w>]$", stripped):
                stack.append(("member-init", i))  # b_{x} in a constructor's initializer list
            elif FUNCTION_END.search(stripped) or INIT_LIST.search(stripped):
                first = line - text[header_start + lead:i].count("\n")
                m = re.search(r"([\w:~]+(?:operator\s*\S+?)?)\s*\(", stripped)
                stack.append(("function", (m.group(1) if m else stripped[:40], first)))
            else:
                stack.append(("block", i))  # an initializer or a nested scope
    return found


def self_test():
    import tempfile

    def body(n):  # a function of n lines in all
        return "int f(int x) {\n" + "  x += 1;  // { not a brace\n" * (n - 3) + '  const char* s = "}";\n}\n'

    cases = [
        (body(121), [("f", 1, 121)]),
        (body(120), [("f", 1, 120)]),
        ("namespace a {\nclass C {\n public:\n  int g() const {\n    return 1;\n  }\n};\n}  // namespace a\n",
         [("g", 4, 6)]),
        ("void h() {\n  auto l = [](int y) {\n    return y;\n  };\n  l(1);\n}\nconst int k[] = {1, 2};\n",
         [("h", 1, 6)]),
        ("S::S(int a)\n    : a_(a), b_{a} {\n  a_ = 2;\n}\n", [("S::S", 1, 4)]),
    ]
    bad = 0
    with tempfile.TemporaryDirectory() as d:
        for k, (text, want) in enumerate(cases):
            path = os.path.join(d, f"case{k}.cpp")
            open(path, "w").write(text)
            got = functions(path)
            if got != want:
                print(f"self-test case {k}: found {got}, expected {want}")
                bad += 1
    print(f"check_structure: self-test {'failed' if bad else 'passed'} ({len(cases)} cases)")
    return 1 if bad else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--exclude", action="append", default=[])
    ap.add_argument("--max-file", type=int, default=600)
    ap.add_argument("--max-function", type=int, default=120)
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--report", type=int, default=80)
    a = ap.parse_args()
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    exclude = {os.path.normpath(os.path.join(root, e)) for e in a.exclude}
    files = []
    for p in a.paths:
        full = os.path.normpath(os.path.join(root, p))
        if os.path.isdir(full):
            for d, _, names in os.walk(full):
                files += [os.path.join(d, f) for f in names if f.endswith((".cpp", ".hpp"))]
        elif os.path.isfile(full):
            files.append(full)
        else:
            print(f"check_structure: {p}: no such file or folder", file=sys.stderr)
            return 2
    bad = []
    listed = []
    for f in sorted(set(files)):
        if f in exclude:
            continue
        rel = os.path.relpath(f, root)
        lines = open(f, encoding="utf-8").read().count("\n")
        if lines > a.max_file:
            bad.append(f"{rel}: {lines} lines, more than {a.max_file}")
        for name, first, last in functions(f):
            n = last - first + 1
            if n > a.max_function:
                bad.append(f"{rel}:{first}: function {name}: {n} lines, more than {a.max_function}")
            elif a.list and n > a.report:
                listed.append((n, f"{rel}:{first}: function {name}: {n} lines"))
        parts = rel.split(os.sep)
        if len(parts) >= 3 and parts[0] == "src" and parts[1] in LAYER_OF:
            own = LAYER_OF[parts[1]]
            for k, text in enumerate(open(f, encoding="utf-8"), 1):
                m = re.match(r'\s*#\s*include\s+"(\w+)/', text)
                if m and m.group(1) in LAYER_OF and LAYER_OF[m.group(1)] > own:
                    bad.append(f"{rel}:{k}: includes {m.group(1)}/ from the lower layer {parts[1]}/ "
                               f"(order: {', '.join('/'.join(g) for g in LAYERS)})")
    for _, text in sorted(listed, reverse=True):
        print(text)
    for text in bad:
        print(text)
    if bad:
        print(f"check_structure: {len(bad)} finding(s)", file=sys.stderr)
        return 1
    print(f"check_structure: {len(set(files)) - len(exclude & set(files))} files: none over "
          f"{a.max_file} lines, no function over {a.max_function} lines, no include from a "
          f"lower layer to a higher one")
    return 0


if __name__ == "__main__":
    sys.exit(main())
