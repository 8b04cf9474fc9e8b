"""A bag's metadata: the structs, metadata.yaml (Humble's version 5) and `ros2 bag info` text."""
import json
import os
import time
from dataclasses import dataclass, field

METADATA_FILENAME = 'metadata.yaml'
METADATA_VERSION = 5  # Humble's rosbag2_storage::BagMetadata::version


@dataclass
class TopicMetadata:
    name: str
    type: str
    serialization_format: str
    offered_qos_profiles: str = ''

    def equals(self, other):
        return self == other


@dataclass
class TopicInformation:
    topic_metadata: TopicMetadata
    message_count: int = 0


@dataclass
class FileInformation:
    path: str
    starting_time: int = 0   # ns since epoch
    duration: int = 0        # ns
    message_count: int = 0


@dataclass
class BagMetadata:
    version: int = METADATA_VERSION
    bag_size: int = 0
    storage_identifier: str = ''
    relative_file_paths: list = field(default_factory=list)
    files: list = field(default_factory=list)
    duration: int = 0        # ns
    starting_time: int = 0   # ns since epoch
    message_count: int = 0
    topics_with_message_count: list = field(default_factory=list)
    compression_format: str = ''
    compression_mode: str = ''

    def __str__(self):
        return format_bag_metadata(self)


# ------------------------------------------------------------------ YAML (yaml-cpp's look)

def _scalar(value):
    if isinstance(value, bool):
        return 'true' if value else 'false'
    if isinstance(value, int):
        return str(value)
    text = str(value)
    plain = text and all(c.isalnum() or c in '/_.-' for c in text) and not text[0] in '-.' \
        and not _looks_special(text)
    return text if plain else json.dumps(text)


def _looks_special(text):
    if text.lower() in ('true', 'false', 'null', 'yes', 'no', 'on', 'off', '~'):
        return True
    try:
        float(text)
        return True
    except ValueError:
        return False


def to_yaml(m):
    """metadata.yaml text as Humble's yaml-cpp emitter writes it."""
    out = ['rosbag2_bagfile_information:',
           f'  version: {m.version}',
           f'  storage_identifier: {_scalar(m.storage_identifier)}',
           '  duration:', f'    nanoseconds: {m.duration}',
           '  starting_time:', f'    nanoseconds_since_epoch: {m.starting_time}',
           f'  message_count: {m.message_count}']
    if m.topics_with_message_count:
        out.append('  topics_with_message_count:')
        for ti in m.topics_with_message_count:
            t = ti.topic_metadata
            out += ['    - topic_metadata:',
                    f'        name: {_scalar(t.name)}',
                    f'        type: {_scalar(t.type)}',
                    f'        serialization_format: {_scalar(t.serialization_format)}',
                    f'        offered_qos_profiles: {_scalar(t.offered_qos_profiles)}',
                    f'      message_count: {ti.message_count}']
    else:
        out.append('  topics_with_message_count: []')
    out += [f'  compression_format: {_scalar(m.compression_format)}',
            f'  compression_mode: {_scalar(m.compression_mode)}']
    if m.relative_file_paths:
        out.append('  relative_file_paths:')
        out += [f'    - {_scalar(p)}' for p in m.relative_file_paths]
    else:
        out.append('  relative_file_paths: []')
    if m.files:
        out.append('  files:')
        for f in m.files:
            out += [f'    - path: {_scalar(f.path)}',
                    '      starting_time:',
                    f'        nanoseconds_since_epoch: {f.starting_time}',
                    '      duration:', f'        nanoseconds: {f.duration}',
                    f'      message_count: {f.message_count}']
    else:
        out.append('  files: []')
    return '\n'.join(out)


def write_metadata(directory, m):
    path = os.path.join(directory, METADATA_FILENAME)
    tmp = path + '.tmp'
    with open(tmp, 'w', encoding='utf-8') as f:
        f.write(to_yaml(m))
    os.replace(tmp, path)  # a reader never sees half a file


class MetadataError(RuntimeError):
    """A metadata.yaml that cannot be read: rosbag2's one line."""


def _yaml_cpp_what(error):
    """What yaml-cpp's exception would say (rosbag2 prints its what())."""
    import yaml
    if isinstance(error, KeyError):       # InvalidNode: no mark
        return f'invalid node; first invalid key: "{error.args[0]}"'
    if isinstance(error, _NotAMap):       # BadSubscript, marked at the document's start
        return ('yaml-cpp: error at line 1, column 1: operator[] call on a scalar '
                '(key: "rosbag2_bagfile_information")')
    mark = getattr(error, 'problem_mark', None)
    if isinstance(error, yaml.MarkedYAMLError) and mark is not None:
        problem, mark = _yaml_cpp_problem(error, mark)
        return f'yaml-cpp: error at line {mark.line + 1}, column {mark.column + 1}: {problem}'
    return 'yaml-cpp: error at line 0, column 0: bad conversion'


def _yaml_cpp_problem(error, mark):
    """yaml-cpp's ErrorMsg (and where it marks it) for what PyYAML found: the same faults,
    other words (yaml-cpp 0.7's exceptions.h, as yaml_cpp_vendor ships it in Humble)."""
    problem = error.problem or error.context or 'parse error'
    context = error.context or ''
    if problem == 'mapping values are not allowed here':
        return 'illegal map value', mark
    if problem.startswith("expected ',' or ']'"):
        return 'end of sequence flow not found', mark
    if problem.startswith("expected ',' or '}'"):
        return 'end of map flow not found', mark
    if problem.startswith('expected <block end>'):
        if 'mapping' in context:
            return 'end of map not found', mark
        return 'end of sequence not found', mark
    if problem == "could not find expected ':'":
        # yaml-cpp meets a scalar where a key should be, where it starts
        return 'end of map not found', error.context_mark or mark
    if problem == 'found unexpected end of stream' and 'quoted scalar' in context:
        return 'illegal EOF in scalar', mark
    if problem.startswith('found undefined alias'):
        return 'the referenced anchor is not defined', mark
    return problem, mark


def read_metadata(directory):
    """Parse metadata.yaml (versions 1-9 as far as Humble's fields go)."""
    try:
        return _read_metadata(directory)
    except OSError:
        raise
    except Exception as e:  # yaml errors, missing keys, wrong types: rosbag2's one line
        raise MetadataError(f'Exception on parsing info file: {_yaml_cpp_what(e)}') from None


class _NotAMap(Exception):
    pass


def _read_metadata(directory):
    import yaml
    with open(os.path.join(directory, METADATA_FILENAME), encoding='utf-8') as f:
        document = yaml.safe_load(f)
    if not isinstance(document, dict):
        raise _NotAMap()
    node = document['rosbag2_bagfile_information']
    version = int(node['version'])
    topics = []
    for ti in node.get('topics_with_message_count') or []:
        t = ti['topic_metadata']
        qos = t.get('offered_qos_profiles', '') if version >= 4 else ''
        if not isinstance(qos, str):  # version 9 writes a list
            qos = yaml.safe_dump(qos, sort_keys=False).rstrip('\n') if qos else ''
        topics.append(TopicInformation(
            TopicMetadata(t['name'], t['type'], t['serialization_format'], qos),
            int(ti['message_count'])))
    files = [FileInformation(f['path'], int(f['starting_time']['nanoseconds_since_epoch']),
                             int(f['duration']['nanoseconds']), int(f['message_count']))
             for f in (node.get('files') or [])]
    return BagMetadata(
        version=version,
        storage_identifier=node['storage_identifier'],
        relative_file_paths=list(node.get('relative_file_paths') or []),
        files=files,
        duration=int(node['duration']['nanoseconds']),
        starting_time=int(node['starting_time']['nanoseconds_since_epoch']),
        message_count=int(node['message_count']),
        topics_with_message_count=topics,
        compression_format=node.get('compression_format', '') or '',
        compression_mode=node.get('compression_mode', '') or '',
    )


def directory_size(directory):
    """Humble's bag size: every regular file in the bag folder (metadata.yaml included)."""
    total = 0
    for entry in os.scandir(directory):
        if entry.is_file():
            total += entry.stat().st_size
    return total


# --------------------------------------------------------------------------- info text

def _split_ns(ns):
    seconds, frac = divmod(int(ns), 1_000_000_000)
    return seconds, f'{frac:09d}'


def format_duration(ns):
    seconds, frac = _split_ns(ns)
    return f'{seconds}.{frac}'


def format_time_point(ns):
    seconds, frac = _split_ns(ns)
    tm = time.localtime(seconds)
    date = time.strftime('%b ', tm) + f'{tm.tm_mday:>2}' + time.strftime(' %Y', tm)
    return f'{date} {time.strftime("%H:%M:%S", tm)}.{frac} ({seconds}.{frac})'


def format_file_size(size):
    units = ['B', 'KiB', 'MiB', 'GiB', 'TiB']
    value, index = float(size), 0
    while value >= 1024 and index < 4:
        value /= 1024
        index += 1
    return f'{value:.{0 if index == 0 else 1}f} {units[index]}'


_INDENT = ' ' * 19  # the longest field name ("Topic information: ") is the column


def format_bag_metadata(m):
    """What `ros2 bag info` prints (rosbag2_py's format_bag_meta_data)."""
    files = m.relative_file_paths
    lines = ['', 'Files:             ' + (files[0] if files else '')]
    lines += [_INDENT + p for p in files[1:]]
    lines += [f'Bag size:          {format_file_size(m.bag_size)}',
              f'Storage id:        {m.storage_identifier}',
              f'Duration:          {format_duration(m.duration)}s',
              f'Start:             {format_time_point(m.starting_time)}',
              f'End:               {format_time_point(m.starting_time + m.duration)}',
              f'Messages:          {m.message_count}']
    topics = [f'Topic: {t.topic_metadata.name} | Type: {t.topic_metadata.type} | '
              f'Count: {t.message_count} | Serialization Format: '
              f'{t.topic_metadata.serialization_format}'
              for t in m.topics_with_message_count]
    lines.append('Topic information: ' + (topics[0] if topics else ''))
    lines += [_INDENT + t for t in topics[1:]]
    return '\n'.join(lines) + '\n'
