"""`ros2 bag record|info|play` (ros2bag's verbs, Humble's options, texts and log lines).

record and play run as background jobs (a labkit process each); info is a short verb.
"""
import argparse
import datetime
import os

from labkit.commands import add_verbs

STORAGE_CHOICES = ['mcap', 'sqlite3']


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('info', 'Print information about a bag to the screen', _info_args, info),
        ('play', 'Play back ROS data from a bag', _play_args, play),
        ('record', 'Record ROS data to a bag', _record_args, record),
        ('reindex', 'Reconstruct metadata file for a bag', _reader_args, reindex),
    ])


def print_error(text):
    return f'[ERROR] [ros2bag]: {text}'


# --------------------------------------------------------------------------- argument checks

def check_path_exists(value):
    if os.path.exists(value):
        return value
    raise argparse.ArgumentTypeError(f"Bag path '{value}' does not exist!")


def check_positive_float(value):
    try:
        fvalue = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f'{value} is not the valid type (float)')
    if fvalue <= 0.0:
        raise argparse.ArgumentTypeError(f'{value} is not in the valid range (> 0.0)')
    return fvalue


def check_not_negative_float(value):
    try:
        fvalue = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f'{value} is not the valid type (float)')
    if fvalue < 0.0:
        raise argparse.ArgumentTypeError(f'Value {value} is less than zero.')
    return fvalue


def _reader_args(p):
    p.add_argument('bag_path', type=check_path_exists, help='Bag to open')
    p.add_argument('-s', '--storage', default='', choices=STORAGE_CHOICES,
                   help='Storage implementation of bag. By default attempts to detect '
                        'automatically - use this argument to override.')


# --------------------------------------------------------------------------- info

def _info_args(p):
    _reader_args(p)


def info(args, io):
    from labkit.bag.storage import BagError, info_metadata
    try:
        metadata = info_metadata(args.bag_path, args.storage)
    except BagError as e:
        return str(e)
    io.print(metadata)


# --------------------------------------------------------------------------- reindex

def reindex(args, io):
    """Rebuild metadata.yaml from the bag's files (a recording that was killed); an mcap
    file cut short by the kill is first rewritten whole from its complete chunks."""
    from labkit.bag.mcap_file import recover
    from labkit.bag.metadata import METADATA_FILENAME, write_metadata
    from labkit.bag.storage import BagError, read_bag_metadata, storage_files
    if not os.path.isdir(args.bag_path):
        return print_error('Must specify a bag directory')
    stale = os.path.join(args.bag_path, METADATA_FILENAME)
    if os.path.exists(stale):
        os.remove(stale)
    for name in storage_files(args.bag_path):
        if name.endswith('.mcap'):
            try:
                recover(os.path.join(args.bag_path, name))
            except (OSError, ValueError):
                return 'No storage could be initialized from the inputs.'
    try:
        metadata = read_bag_metadata(args.bag_path, args.storage)
    except BagError as e:
        return str(e)
    write_metadata(args.bag_path, metadata)


# --------------------------------------------------------------------------- record

def _record_args(p):
    p.add_argument('topics', nargs='*', default=None, help='List of topics to record.')
    p.add_argument('-a', '--all', action='store_true',
                   help='Record all topics. Required if no explicit topic list or regex '
                        'filters.')
    p.add_argument('-e', '--regex', default='',
                   help='Record only topics containing provided regular expression. '
                        'Applies on top of topics list.')
    p.add_argument('-x', '--exclude', default='',
                   help='Exclude topics containing provided regular expression. '
                        'Works on top of --all, --regex, or topics list.')
    p.add_argument('--include-unpublished-topics', action='store_true',
                   help='Discover and record topics which have no publisher. Subscriptions '
                        'on such topics will be made with default QoS unless otherwise '
                        'specified in a QoS overrides file.')
    p.add_argument('--include-hidden-topics', action='store_true',
                   help='Discover and record hidden topics as well. These are topics used '
                        'internally by ROS 2 implementation.')
    p.add_argument('-o', '--output',
                   help='destination of the bagfile to create, defaults to a timestamped '
                        'folder in the current directory')
    p.add_argument('-s', '--storage', default='sqlite3', choices=STORAGE_CHOICES,
                   help="storage identifier to be used, defaults to 'sqlite3'")
    p.add_argument('-f', '--serialization-format', default='', choices=['cdr'],
                   help='rmw serialization format in which the messages are saved, defaults '
                        'to the rmw currently in use')
    p.add_argument('--no-discovery', action='store_true',
                   help='disables topic auto discovery during recording: only topics present '
                        'at startup will be recorded')
    p.add_argument('-p', '--polling-interval', type=int, default=100,
                   help='time in ms to wait between querying available topics for recording. '
                        'It has no effect if --no-discovery is enabled.')
    p.add_argument('-b', '--max-bag-size', type=int, default=0,
                   help='maximum size in bytes before the bagfile will be split. Default it is '
                        'zero, recording written in single bagfile and splitting is disabled.')
    p.add_argument('-d', '--max-bag-duration', type=int, default=0,
                   help='maximum duration in seconds before the bagfile will be split. '
                        'Default is zero, recording written in single bagfile and splitting '
                        'is disabled.')
    p.add_argument('--max-cache-size', type=int, default=100 * 1024 * 1024,
                   help='maximum size (in bytes) of messages to hold in each buffer of cache.')
    p.add_argument('--start-paused', action='store_true', default=False,
                   help='Start the recorder in a paused state.')
    p.add_argument('--log-level', type=str, default='info',
                   choices=['debug', 'info', 'warn', 'error', 'fatal'], help='Logging level.')
    p.set_defaults(_background=lambda a: _record_problem(a) is None)


def _record_problem(args):
    """Humble's checks before recording starts (one error line, exit 1)."""
    if args.all and args.topics:
        return print_error('Specify either --all or topics, but not both simultaneously.')
    if not (args.all or args.topics or args.regex):
        return print_error('Invalid choice: Must specify topic(s), --regex or --all')
    if args.topics and args.exclude:
        return print_error('--exclude argument cannot be used when specifying a list '
                           'of topics explicitly')
    if args.exclude and not (args.regex or args.all):
        return print_error('--exclude argument requires either --all or --regex')
    if args.output and os.path.isdir(args.output):
        return print_error(f"Output folder '{args.output}' already exists.")
    return None


def default_bag_name():
    from labkit.graph import world
    stamp = datetime.datetime.fromtimestamp(world.system_ns() / 1e9)
    return stamp.strftime('rosbag2_%Y_%m_%d-%H_%M_%S')


def record(args, io):
    problem = _record_problem(args)
    if problem is not None:
        return problem
    if args.all and args.regex:
        io.print('[WARN] [ros2bag]: --all will override --regex.')
    args.output = args.output or default_bag_name()
    if os.path.isdir(args.output):
        return print_error(f"Output folder '{args.output}' already exists.")
    from labkit.bag.recorder import Recorder
    Recorder(args).record()


# --------------------------------------------------------------------------- play

def _play_args(p):
    _reader_args(p)
    p.add_argument('--read-ahead-queue-size', type=int, default=1000,
                   help='size of message queue rosbag tries to hold in memory to help '
                        'deterministic playback.')
    p.add_argument('-r', '--rate', type=check_positive_float, default=1.0,
                   help='rate at which to play back messages. Valid range > 0.0.')
    p.add_argument('--topics', type=str, default=[], nargs='+',
                   help='topics to replay, separated by space. If none specified, all topics '
                        'will be replayed.')
    p.add_argument('-l', '--loop', action='store_true',
                   help='enables loop playback when playing a bagfile: it starts back at the '
                        'beginning on reaching the end and plays indefinitely.')
    p.add_argument('--remap', '-m', default='', nargs='+',
                   help='list of topics to be remapped: in the form '
                        '"old_topic1:=new_topic1 old_topic2:=new_topic2 etc." ')
    p.add_argument('-d', '--delay', type=check_not_negative_float, default=0.0,
                   help='Sleep duration before play (each loop), in seconds. Negative '
                        'durations invalid.')
    p.add_argument('--disable-keyboard-controls', action='store_true',
                   help='disables keyboard controls for playback')
    p.add_argument('-p', '--start-paused', action='store_true', default=False,
                   help='Start the playback player in a paused state.')
    p.add_argument('--start-offset', type=check_not_negative_float, default=0.0,
                   help='Start the playback player this many seconds into the bag file.')
    p.add_argument('--log-level', type=str, default='info',
                   choices=['debug', 'info', 'warn', 'error', 'fatal'], help='Logging level.')
    p.set_defaults(_background=lambda a: True)


def play(args, io):
    from labkit.bag.player import Player
    from labkit.bag.storage import BagError, BagReader
    try:   # Humble's Player opens the bag before it plays: its error is a plain line
        reader = BagReader(args.bag_path, args.storage)
    except BagError as e:
        return str(e)
    try:
        return Player(args).play(reader)
    except BagError as e:
        return f'[ERROR] [rosbag2_player]: Failed to play: {e}'
