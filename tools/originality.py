"""Fingerprints of the official ROS 2 sources, to check that our code is our own.

The rule (issue 12): no run of 200 characters of a book code cell or a file labkit
ships may be identical to the official tutorials and sources. Import lines, the files
`ros2 pkg create` generates and license texts are excepted; so are a program's own
output texts (usage, help, messages) in labkit's implementation.

We cannot keep the official sources in the repository, so we keep hashes:

    python tools/originality.py build REF_DIR [REF_DIR ...]   # writes FINGERPRINTS
    python tools/originality.py check                          # our texts against them

How. Both sides are normalised alike (import lines dropped, every run of whitespace one
space). Every WINDOW-character window of an official file gets a 64-bit hash; of each
SPAN consecutive windows only the smallest hash is kept ("winnowing"), so the file holds
about 2/(SPAN+1) of them, 6 bytes each, sorted, and no readable text at all. A common
run of WINDOW + SPAN - 1 characters or more always contains a kept window, so it is
always found; shorter runs from WINDOW characters on are found most of the time.
Any hit is a real common run of at least WINDOW characters (a 48-bit hash does not
collide by chance at these sizes). tools/longest_run.py measures runs exactly when the
official sources are at hand.
"""
import glob
import hashlib
import io
import json
import os
import re
import sys
import tokenize

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FINGERPRINTS = os.path.join(ROOT, 'tests', 'book', 'originality_fingerprints.bin')
WINDOW = 200
SPAN = 56
HASH_BYTES = 6
ALLOWED_GRAM = 30       # a piece of our text shared this long with a template is excepted
MASK = '\x00'           # stands for excepted text: no official window contains it

REF_SUFFIXES = ('.py', '.rst', '.xml', '.yaml', '.yml', '.md', '.cpp', '.hpp', '.h',
                '.launch', '.txt', '.urdf', '.xacro', '.sdf', '.world', '.rviz', '.cfg',
                '.ini', '.sh', '.bash', '.json', '.em', '.in')
OUR_SUFFIXES = REF_SUFFIXES + ('.dsv', '.ps1', '.zsh', '.js', '.css', '.toml')
IMPORT = re.compile(r'^[ \t]*(from[ \t]+\S+[ \t]+)?import[ \t].*$', re.M)


def normalise(text):
    """Import lines out, every run of whitespace one space."""
    return ' '.join(IMPORT.sub('', text).split())


def _hash(window):
    digest = hashlib.blake2b(window.encode('utf-8'), digest_size=HASH_BYTES).digest()
    return int.from_bytes(digest, 'big')


def window_hashes(text):
    return [_hash(text[i:i + WINDOW]) for i in range(len(text) - WINDOW + 1)]


def winnow(hashes):
    """The smallest hash of every SPAN consecutive ones (each kept once)."""
    kept = set()
    for i in range(max(len(hashes) - SPAN + 1, 1)):
        block = hashes[i:i + SPAN]
        if block:
            kept.add(min(block))
    return kept


# ------------------------------------------------------------------ official side

def reference_texts(folders):
    for folder in folders:
        for path in sorted(glob.glob(os.path.join(folder, '**', '*'), recursive=True)):
            if path.endswith(REF_SUFFIXES) and os.path.isfile(path):
                try:
                    with open(path, encoding='utf-8') as f:
                        yield path, f.read()
                except (UnicodeDecodeError, OSError):
                    continue


def build(folders, out=FINGERPRINTS):
    kept = set()
    for _, text in reference_texts(folders):
        kept |= winnow(window_hashes(normalise(text)))
    with open(out, 'wb') as f:
        for h in sorted(kept):
            f.write(h.to_bytes(HASH_BYTES, 'big'))
    return len(kept)


def load(path=FINGERPRINTS):
    with open(path, 'rb') as f:
        data = f.read()
    return {int.from_bytes(data[i:i + HASH_BYTES], 'big')
            for i in range(0, len(data), HASH_BYTES)}


# ------------------------------------------------------------------ our side

def allowed_texts():
    """What `ros2 pkg create` generates (every build type, with a node and a library,
    Apache-2.0) and the license texts labkit ships: our texts may repeat these."""
    import contextlib
    import tempfile
    from labkit.ament import create
    texts = []
    for path in glob.glob(os.path.join(ROOT, 'labkit', 'ament', 'licenses', '*.txt')):
        with open(path, encoding='utf-8') as f:
            texts.append(f.read())
    variants = [(build_type, extra)
                for build_type in ('ament_python', 'ament_cmake', 'cmake')
                for extra in ([], ['--node-name', 'my_node'], ['--library-name', 'my_library'])
                if not (build_type == 'ament_python' and 'my_library' in extra)]
    with tempfile.TemporaryDirectory() as tmp:
        for k, (build_type, extra) in enumerate(variants):
            argv = [f'my_package_{k}', '--build-type', build_type, '--license', 'Apache-2.0',
                    '--dependencies', 'rclpy', 'std_msgs', '--destination-directory',
                    tmp] + extra
            with contextlib.redirect_stdout(io.StringIO()), \
                    contextlib.redirect_stderr(io.StringIO()):
                create.main(argv)
        for path in sorted(glob.glob(os.path.join(tmp, '**', '*'), recursive=True)):
            if os.path.isfile(path):
                with open(path, encoding='utf-8', errors='replace') as f:
                    texts.append(f.read())
    return texts


def allowed_grams(texts):
    grams = set()
    for text in texts:
        flat = normalise(text)
        grams.update(flat[i:i + ALLOWED_GRAM] for i in range(len(flat) - ALLOWED_GRAM + 1))
    return grams


def mask_allowed(flat, grams):
    """Our normalised text with every piece it shares with the allowed texts masked."""
    masked = [False] * len(flat)
    for i in range(len(flat) - ALLOWED_GRAM + 1):
        if flat[i:i + ALLOWED_GRAM] in grams:
            masked[i:i + ALLOWED_GRAM] = [True] * ALLOWED_GRAM
    return ''.join(MASK if m else c for c, m in zip(flat, masked))


def without_strings(source):
    """Python source with every string literal replaced by MASK: a program's output
    texts (usage, help, messages) are the real program's words, not code."""
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(source).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return source
    lines = source.splitlines(keepends=True)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))
    out, pos = [], 0
    for tok in tokens:
        if tok.type != tokenize.STRING:
            continue
        a = starts[tok.start[0] - 1] + tok.start[1]
        b = starts[tok.end[0] - 1] + tok.end[1]
        out.append(source[pos:a])
        out.append(MASK)
        pos = b
    out.append(source[pos:])
    return ''.join(out)


def _files(folder):
    for root, dirs, names in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and d != '__pycache__')
        for name in sorted(names):
            if name.endswith(OUR_SUFFIXES) or '.' not in name:
                yield os.path.join(root, name)


def _read(path):
    try:
        with open(path, encoding='utf-8') as f:
            return f.read()
    except (UnicodeDecodeError, OSError):
        return None


def shown_texts(root=ROOT):
    """[(label, text)] of what the reader sees or runs as an example: the book's code
    cells, the facer sources, every file in labkit's install prefixes, the demos,
    the tf2 demo package and the package templates."""
    out = []
    for nb in sorted(glob.glob(os.path.join(root, 'book', '**', '*.ipynb'), recursive=True)):
        rel = os.path.relpath(nb, root)
        if '/_build/' in nb or '/_work/' in nb or '.ipynb_checkpoints' in nb:
            continue
        with open(nb, encoding='utf-8') as f:
            cells = json.load(f)['cells']
        for i, cell in enumerate(cells):
            if cell['cell_type'] == 'code':
                out.append((f'{rel} cell {i}', ''.join(cell['source'])))
    folders = glob.glob(os.path.join(root, 'book', '**', 'facer_src'), recursive=True)
    folders += glob.glob(os.path.join(root, 'labkit', '**', 'prefix'), recursive=True)
    folders += [os.path.join(root, 'labkit', 'demos'),
                os.path.join(root, 'labkit', 'tf2', 'turtle_demo')]
    paths = [p for folder in sorted(folders) for p in _files(folder)]
    paths.append(os.path.join(root, 'labkit', 'ament', 'templates.py'))
    for path in paths:
        text = _read(path)
        if text is not None:
            out.append((os.path.relpath(path, root), text))
    return out


def source_texts(root=ROOT, shown=()):
    """[(label, text)] of labkit's implementation (its .py files not in shown_texts),
    string literals masked."""
    seen = set(shown)
    out = []
    for path in _files(os.path.join(root, 'labkit')):
        rel = os.path.relpath(path, root)
        if not path.endswith('.py') or rel in seen or '/prefix/' in rel:
            continue
        text = _read(path)
        if text is not None:
            out.append((rel, without_strings(text)))
    return out


def shared_runs(flat, fingerprints):
    """[(start, end)] of our normalised text covered by windows found in the fingerprints
    (merged when they touch): each is at least WINDOW characters identical upstream."""
    runs = []
    for i in range(len(flat) - WINDOW + 1):
        window = flat[i:i + WINDOW]
        if MASK in window or _hash(window) not in fingerprints:
            continue
        if runs and i <= runs[-1][1]:
            runs[-1][1] = i + WINDOW
        else:
            runs.append([i, i + WINDOW])
    return [tuple(r) for r in runs]


def check(texts, fingerprints, grams):
    """{label: [(length, excerpt)]} of our texts that share runs with the official ones."""
    found = {}
    for label, text in texts:
        flat = mask_allowed(normalise(text), grams)
        runs = shared_runs(flat, fingerprints)
        if runs:
            found[label] = [(b - a, flat[a:a + 60]) for a, b in runs]
    return found


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ['build'] and argv[1:]:
        n = build(argv[1:])
        print(f'{n} fingerprints written to {os.path.relpath(FINGERPRINTS)} '
              f'({os.path.getsize(FINGERPRINTS)} bytes)')
        return 0
    if argv[:1] == ['check']:
        fingerprints = load()
        grams = allowed_grams(allowed_texts())
        shown = shown_texts()
        texts = shown + source_texts(shown=[label for label, _ in shown])
        found = check(texts, fingerprints, grams)
        for label, runs in sorted(found.items(), key=lambda kv: -max(r[0] for r in kv[1])):
            for length, excerpt in runs:
                print(f'{length:6d}+ {label}: {excerpt!r}')
        print(f'{len(found)} of {len(texts)} texts share {WINDOW}+ characters with the '
              'official sources')
        return 1 if found else 0
    print(__doc__)
    return 2


if __name__ == '__main__':
    sys.exit(main())
