#!/usr/bin/env python3
"""The README's map of src/ (its "Layout" section) is the layering: its rooms are listed from the
bottom up, and a file may include only headers of its own room or of rooms listed before it, so a
picture of the include graph reads top-down with no arrow running back up (issue 49). A room is
the deepest listed folder (or file) that holds a file. The map must also match the tree: every
listed room exists, and every folder directly under src/, src/gx/ and src/paths/ is listed.

A guard, not a parser: it reads `#include "..."` lines, which is how the tree names its headers
(from src/). `--self-test` shows it catches each kind of fault in a tree made for the purpose.

usage: layering_test.py ROOT | --self-test
"""
import pathlib
import re
import sys
import tempfile

ROOM = re.compile(r'^(src/\S+)')
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def rooms_of(readme):
    """The rooms of the README's Layout block, bottom first, as paths relative to src/."""
    text = readme.read_text()
    start = text.index('## Layout')
    block = text[text.index('```', start) + 3:]
    block = block[:block.index('```')]
    rooms = []
    for line in block.splitlines():
        m = ROOM.match(line)
        if m:
            rooms.append(m.group(1)[len('src/'):].rstrip('/'))
    return rooms


def room_of(rel, rooms):
    """The deepest room holding `rel` (a path relative to src/), or None."""
    best = None
    for r in rooms:
        if rel == r or rel.startswith(r + '/'):
            if best is None or len(r) > len(best):
                best = r
    return best


def faults(root):
    src = root / 'src'
    rooms = rooms_of(root / 'README.md')
    rank = {r: i for i, r in enumerate(rooms)}
    out = []
    for r in rooms:
        if not (src / r).exists():
            out.append(f'README.md: the map lists src/{r}, which does not exist')
    for parent in (src, src / 'gx', src / 'paths'):
        for d in sorted(p for p in parent.iterdir() if p.is_dir()):
            rel = d.relative_to(src).as_posix()
            if rel not in rank:
                out.append(f'README.md: the map does not list src/{rel}/')
    for f in sorted(src.rglob('*')):
        if f.suffix not in ('.h', '.cpp', '.c'):
            continue
        rel = f.relative_to(src).as_posix()
        mine = room_of(rel, rooms)
        if mine is None:
            continue
        for number, line in enumerate(f.read_text(errors='replace').splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            theirs = room_of(m.group(1), rooms)
            if theirs is None or theirs == mine or not (src / m.group(1)).exists():
                continue
            if rank[theirs] > rank[mine]:
                out.append(f'src/{rel}:{number}: includes {m.group(1)} (room src/{theirs}/, listed '
                           f'above src/{mine}/ in the README map: an arrow running back up)')
    return out


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for d in ('src/low', 'src/high', 'src/gx', 'src/paths/one', 'src/stray'):
            (root / d).mkdir(parents=True)
        (root / 'README.md').write_text(
            '## Layout\n\n```\nsrc/low/   the bottom\nsrc/gx/    a machine\nsrc/paths/ paths\n'
            'src/paths/one/ a path\nsrc/high/  the top\nsrc/gone/  nothing\n```\n')
        (root / 'src/high/a.h').write_text('#include "low/b.h"\n')
        (root / 'src/low/b.h').write_text('#include "high/a.h"\n')
        (root / 'src/paths/one/c.cpp').write_text('#include "paths/one/c.h"\n#include "low/b.h"\n')
        (root / 'src/paths/one/c.h').write_text('')
        (root / 'src/paths/two').mkdir()
        found = faults(root)
        expected = ['src/low/b.h:1: includes high/a.h', 'lists src/gone', 'not list src/stray/',
                    'not list src/paths/two/']
        missing = [e for e in expected if not any(e in f for f in found)]
        wrong = [f for f in found if 'paths/one/c.cpp' in f or 'high/a.h:' in f]
        if missing or wrong or len(found) != len(expected):
            print('self-test failed: found', found)
            return 1
    print('self-test: each kind of fault found')
    return 0


def main():
    if sys.argv[1:] == ['--self-test']:
        return self_test()
    found = faults(pathlib.Path(sys.argv[1]))
    for f in found:
        print(f)
    print(f'{len(found)} faults')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
