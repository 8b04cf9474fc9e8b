"""Longest run of identical characters between our code and a folder of reference sources.

    python tools/longest_run.py --ref REFERENCE_DIR [REFERENCE_DIR ...] -- OURS [OURS ...]

OURS are notebooks (each code cell is one text), files, or folders (every text file in
them). The references are read from the given folders only (nothing is downloaded and
nothing of theirs is kept): source, documentation, model and config files (REF_SUFFIXES;
interface definitions .msg .srv .action are left out: those must be identical).
Prints, per text of ours, the longest run it shares with any reference file (length,
where), longest first, and exits 1 when a run reaches --limit characters (default 200).

Whitespace is compared loosely by default (every run of spaces, tabs and newlines counts
as one space, so a file indented into an .rst code block still matches); --exact turns
that off. Import lines are excepted by the rule, so --skip-imports leaves out every
`import x` / `from x import y` line on both sides before comparing. Lengths are counted in the texts as compared.

How: every window of ANCHOR characters of ours goes into a dict; the references are
scanned window by window; each hit is grown both ways to the full common run. A run of
length >= ANCHOR always contains a whole window, so nothing of that length is missed.
"""
import argparse
import json
import os
import re
import sys

ANCHOR = 40
REF_SUFFIXES = ('.py', '.rst', '.xml', '.yaml', '.yml', '.md', '.cpp', '.hpp', '.h', '.launch', '.txt',
                '.urdf', '.xacro', '.sdf', '.world', '.rviz', '.cfg', '.ini', '.sh', '.bash', '.json', '.em', '.in')


def our_texts(paths):
    """[(label, text)]: notebook code cells, files, files under folders."""
    out = []
    for path in paths:
        if os.path.isdir(path):
            for root, dirs, files in os.walk(path):
                dirs[:] = sorted(d for d in dirs if not d.startswith(('.', '__pycache__')))
                for name in sorted(files):
                    out.extend(our_texts([os.path.join(root, name)]))
        elif path.endswith('.ipynb'):
            with open(path, encoding='utf-8') as handle:
                nb = json.load(handle)
            for i, cell in enumerate(nb['cells']):
                if cell['cell_type'] == 'code':
                    source = ''.join(cell['source'])
                    out.append((f'{path} cell {i}', source))
        else:
            try:
                with open(path, encoding='utf-8') as handle:
                    out.append((path, handle.read()))
            except (UnicodeDecodeError, OSError):
                pass
    return out


IMPORT = re.compile(r'^[ \t]*(from[ \t]+\S+[ \t]+)?import[ \t].*$', re.M)


def without_imports(text):
    """The text with its Python import lines blanked out."""
    return IMPORT.sub('', text)


def squeeze(text):
    """Every run of whitespace becomes one space."""
    return ' '.join(text.split())


def reference_files(folders):
    for folder in folders:
        for root, dirs, files in os.walk(folder):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(REF_SUFFIXES):
                    path = os.path.join(root, name)
                    try:
                        with open(path, encoding='utf-8') as handle:
                            yield os.path.relpath(path, folder), handle.read()
                    except (UnicodeDecodeError, OSError):
                        continue


def longest_runs(ours, references, anchor=ANCHOR):
    """{our label: (length, reference name, run text)} for every text sharing >= anchor."""
    index = {}
    for k, (_, text) in enumerate(ours):
        for i in range(len(text) - anchor + 1):
            index.setdefault(text[i:i + anchor], []).append((k, i))
    best = {}
    for ref_name, ref in references:
        done = set()          # (our text, offset between the texts) already grown
        for j in range(len(ref) - anchor + 1):
            hits = index.get(ref[j:j + anchor])
            if not hits:
                continue
            for k, i in hits:
                if (k, i - j) in done:
                    continue
                text = ours[k][1]
                a, b = i, j
                while a > 0 and b > 0 and text[a - 1] == ref[b - 1]:
                    a, b = a - 1, b - 1
                e, f = i + anchor, j + anchor
                while e < len(text) and f < len(ref) and text[e] == ref[f]:
                    e, f = e + 1, f + 1
                done.add((k, i - j))
                label = ours[k][0]
                if e - a > best.get(label, (0,))[0]:
                    best[label] = (e - a, ref_name, text[a:e])
    return best


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--limit', type=int, default=200)
    parser.add_argument('--show', action='store_true', help='print each run found')
    parser.add_argument('--exact', action='store_true', help='compare whitespace exactly')
    parser.add_argument('--skip-imports', action='store_true', help='leave out import lines')
    parser.add_argument('--ref', nargs='+', required=True, help='folders of reference sources')
    parser.add_argument('ours', nargs='+', help='notebooks, files or folders of ours')
    args = parser.parse_args(argv)
    ours = our_texts(args.ours)
    references = reference_files(args.ref)
    if args.skip_imports:
        ours = [(label, without_imports(text)) for label, text in ours]
        references = ((name, without_imports(text)) for name, text in references)
    if not args.exact:
        ours = [(label, squeeze(text)) for label, text in ours]
        references = ((name, squeeze(text)) for name, text in references)
    best = longest_runs(ours, references)
    for label, (length, ref_name, run) in sorted(best.items(), key=lambda kv: -kv[1][0]):
        print(f'{length:6d}  {label}  ~  {ref_name}')
        if args.show:
            print('        ' + run.replace('\n', '\n        '))
    longest = max([v[0] for v in best.values()] + [0])
    print(f'longest run: {longest} characters ({len(ours)} texts of ours)')
    return 1 if longest >= args.limit else 0


if __name__ == '__main__':
    sys.exit(main())
