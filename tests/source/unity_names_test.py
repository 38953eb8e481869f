#!/usr/bin/env python3
"""The core, the command layer and the test binaries are unity builds (CMakeLists.txt): sixteen or
thirty-two .cpp files compiled as one translation unit. There, two files' functions of one name with internal linkage (anonymous
namespace or `static`) are overloads of each other, and a call can resolve to the other file's
without a word from the compiler -- the one way a unity build changes behaviour silently (two
definitions of one signature, or of one type or variable, are compile errors instead). So no
function name may have internal linkage in two files under the folder checked (src/, tests/),
whatever their namespaces, and no `using namespace` may stand at file scope (it would reach the files after it).

A guard, not a parser: it reads clang-formatted code, where a definition at namespace scope starts
in column 0. `--self-test` shows it catches both faults in a tree made for the purpose.

usage: unity_names_test.py DIR | --self-test
"""
import collections
import pathlib
import re
import sys
import tempfile

FUNCTION = re.compile(r'^(?:static\s+|inline\s+|constexpr\s+|template\s*<[^>]*>\s*)*'
                      r'[\w:<>,\s\*&\[\]]+?[\s\*&](\w+)\s*\(')
NOT_FUNCTION = re.compile(r'^(?:struct|class|enum|union|using|namespace|typedef|return)\b|'
                          r'^(?:static\s+)?(?:constexpr|const|static)\s[^=(;]*?\b\w+\s*'
                          r'(?:\[[^\]]*\])?\s*(?:=|\{|;)')
KEYWORDS = {'if', 'for', 'while', 'switch', 'return', 'operator', 'sizeof', 'alignof'}
# GoogleTest's printer hook: each test file overloads it for its own parameter type, which is
# what it is for (two of one type would be a compile error, not a silent choice).
OVERLOADS_BY_DESIGN = {'PrintTo'}


def internal_functions(path):
    """(name, line) of the functions `path` defines in an anonymous namespace or as `static`."""
    found, anonymous = [], False
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if re.match(r'^namespace\s*\{', line):
            anonymous = True
            continue
        if anonymous and re.match(r'^\}\s*//\s*namespace\s*$', line):
            anonymous = False
            continue
        if not (anonymous or line.startswith('static ')) or not line[:1].strip():
            continue
        if line[0] in '/#}' or NOT_FUNCTION.match(line):
            continue
        m = FUNCTION.match(line)
        if m and m.group(1) not in KEYWORDS | OVERLOADS_BY_DESIGN:
            found.append((m.group(1), number))
    return found


def faults(src):
    src = pathlib.Path(src)
    where = collections.defaultdict(list)
    out = []
    for f in sorted(src.rglob('*.cpp')):
        rel = f.relative_to(src)
        for name, line in internal_functions(f):
            where[name].append(f'{rel}:{line}')
        for number, line in enumerate(f.read_text().splitlines(), 1):
            if re.match(r'^using namespace\b', line):
                out.append(f'{rel}:{number}: `using namespace` at file scope reaches the next files '
                           'of its unity batch; put it in the function that needs it')
    for name, places in sorted(where.items()):
        if len({p.rsplit(':', 1)[0] for p in places}) > 1:
            out.append(f'{places[0]}: internal function `{name}` is also defined at '
                       f'{", ".join(places[1:])}: in one unity batch they overload each other')
    return out


def self_test():
    with tempfile.TemporaryDirectory() as d:
        root = pathlib.Path(d)
        (root / 'a').mkdir()
        (root / 'a/one.cpp').write_text('namespace lt {\nnamespace {\n\nfloat scale(float v) {\n'
                                        '  return v;\n}\n\n}  // namespace\n}  // namespace lt\n')
        (root / 'a/two.cpp').write_text('namespace lt::x {\n\nusing namespace y;\n\n'
                                        'static double scale(double v) { return v; }\n'
                                        'constexpr int kOnly = 1;\n}  // namespace lt::x\n')
        (root / 'a/three.cpp').write_text('namespace lt {\nnamespace {\nstruct scale {};\n'
                                          'constexpr float kOnly = 2;\n}  // namespace\n'
                                          'int exported(int v) { return v; }\n}  // namespace lt\n')
        found = faults(root)
        expected = ['a/two.cpp:3: `using namespace`', 'internal function `scale`']
        missing = [e for e in expected if not any(e in f for f in found)]
        extra = [f for f in found if not any(e in f for e in expected)]
        if missing or extra or len(found) != 2:
            print('self-test failed; found:', *found, sep='\n  ')
            return 1
        print('self-test: both faults found, nothing else')
        return 0


def main():
    if sys.argv[1:] == ['--self-test']:
        return self_test()
    found = faults(sys.argv[1])
    for f in found:
        print(f)
    print(f'{len(found)} faults' if found else 'no internal function name in two files')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
