#!/usr/bin/env python3
"""Every relative link of the project's Markdown resolves, and every document under docs/ is
linked from the README (so the map of docs/ cannot miss one). Links rot as files move; this is
run by ctest (Docs.Links).

Usage: links_test.py SOURCE_DIR      check the repository; one line per broken link, exit 1
       links_test.py --self-test     check the checker on a tree with known faults

A link is a Markdown inline link [text](target) outside code spans and fenced blocks. A target
with a scheme (https:, mailto:) is not checked. A target's path must name an existing file or
folder, relative to the document; a #fragment on a .md target (or alone) must be the GitHub
anchor of one of its headings (lower case, punctuation but '-' and '_' dropped, spaces to '-',
a repeated heading's anchor suffixed -1, -2, ...)."""
import os
import re
import sys
import tempfile

LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\]]*\])*)\]\(([^()\s]*(?:\([^()\s]*\)[^()\s]*)*)(?:\s+\"[^\"]*\")?\)")
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def markdown_files(root):
    """Every .md file under root, skipping build trees (a CMakeCache.txt), out/ and .git."""
    found = []
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if x not in (".git", "out") and
                         not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        found += [os.path.join(d, f) for f in sorted(files) if f.endswith(".md")]
    return found


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with code spans blanked."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        stripped = line.lstrip()
        marker = re.match(r"(`{3,}|~{3,})", stripped)
        if marker:
            if fence is None:
                fence = marker.group(1)[0] * len(marker.group(1))
            elif stripped.startswith(fence):
                fence = None
            continue
        if fence is None:
            yield number, CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)


def anchor(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def heading_anchors(path):
    """Anchors of the headings as written (code spans included: `x` counts as x)."""
    seen = {}
    out = set()
    fence = None
    for line in open(path, encoding="utf-8").read().split("\n"):
        marker = re.match(r"\s*(`{3,}|~{3,})", line)
        if marker:
            fence = None if fence else marker.group(1)
            continue
        m = None if fence else re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            a = anchor(m.group(1))
            n = seen.get(a, 0)
            seen[a] = n + 1
            out.add(a if n == 0 else "%s-%d" % (a, n))
    return out


def check(root):
    """The faults, as 'file:line: message' lines, and how many links were checked."""
    faults = []
    checked = 0
    readme = os.path.join(root, "README.md")
    linked_from_readme = set()
    anchor_cache = {}
    for doc in markdown_files(root):
        rel_doc = os.path.relpath(doc, root)
        for number, line in prose_lines(open(doc, encoding="utf-8").read()):
            for m in LINK.finditer(line):
                target = m.group(2)
                if not target or SCHEME.match(target):
                    continue
                path, _, fragment = target.partition("#")
                resolved = os.path.normpath(os.path.join(os.path.dirname(doc), path)) if path else doc
                where = "%s:%d: link (%s)" % (rel_doc, number, target)
                checked += 1
                if not os.path.exists(resolved):
                    faults.append("%s: no such file %s" % (where, os.path.relpath(resolved, root)))
                    continue
                if doc == readme:
                    linked_from_readme.add(resolved)
                if fragment and resolved.endswith(".md"):
                    if resolved not in anchor_cache:
                        anchor_cache[resolved] = heading_anchors(resolved)
                    if fragment not in anchor_cache[resolved]:
                        faults.append("%s: %s has no heading with anchor #%s" %
                                      (where, os.path.relpath(resolved, root), fragment))
    docs = os.path.join(root, "docs")
    for doc in markdown_files(docs) if os.path.isdir(docs) else []:
        if doc not in linked_from_readme:
            faults.append("README.md: %s is not linked from the README's map of docs/" %
                          os.path.relpath(doc, root))
    return faults, checked


def self_test():
    """The checker finds each kind of fault in a tree made for it, and nothing in a clean one."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs", "spec"))

        def write(rel, text):
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)

        write("README.md", "# T\n\n[a](docs/a.md), [spec](docs/spec/s.md#2-the-rules-of-x)\n"
                           "`[not a link](nowhere.md)`\n```\n[nor this](nowhere.md)\n```\n")
        write("docs/a.md", "# A\n\n## Same\n\n## Same\n\n[s](spec/s.md) [t](#same-1)\n")
        write("docs/spec/s.md", "# S\n\n## 2. The rules of `x`\n")
        clean, _ = check(root)
        if clean:
            print("self-test: a clean tree reported:\n" + "\n".join(clean))
            return 1
        write("docs/a.md", "# A\n\n[gone](missing.md) [bad anchor](spec/s.md#nope) [t](#same-2)\n")
        write("docs/unlinked.md", "# U\n")
        found, _ = check(root)
        expected = [
            "docs/a.md:3: link (missing.md): no such file docs/missing.md",
            "docs/a.md:3: link (spec/s.md#nope): docs/spec/s.md has no heading with anchor #nope",
            "docs/a.md:3: link (#same-2): docs/a.md has no heading with anchor #same-2",
            "README.md: docs/unlinked.md is not linked from the README's map of docs/",
        ]
        if sorted(found) != sorted(expected):
            print("self-test: expected\n  " + "\n  ".join(expected) + "\nfound\n  " +
                  "\n  ".join(found))
            return 1
    print("self-test: the checker reports a missing file, a missing anchor and an unlinked "
          "document, and nothing on a clean tree")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: links_test.py SOURCE_DIR | --self-test", file=sys.stderr)
        return 2
    root = os.path.abspath(argv[1])
    faults, checked = check(root)
    for fault in faults:
        print(fault)
    print("%d fault(s); %d relative links checked in %d Markdown files" %
          (len(faults), checked, len(markdown_files(root))))
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
