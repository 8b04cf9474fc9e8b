"""`%ros2 connect [DOMAIN_ID] [--lan]` / `%ros2 disconnect`: labkit's own verbs (like
`jobs`), not ros2cli's. A notebook stays in-process until the reader connects."""
from labkit.commands import CompletedCommand

USAGE = 'usage: ros2 connect [DOMAIN_ID] [--lan] | ros2 disconnect'


def connect_command(argv):
    from labkit import dds
    if argv[0] == 'disconnect':
        if len(argv) > 1:
            return CompletedCommand(argv, 2, '', USAGE + '\n')
        was = dds.current()
        dds.disconnect()
        text = (f'left DDS domain {was.domain_id}\n' if was is not None else 'not connected\n')
        return CompletedCommand(argv, 0, text, '')
    domain, lan = None, False
    for arg in argv[1:]:
        if arg == '--lan':
            lan = True
        elif arg.isdigit() and domain is None:
            domain = int(arg)
        else:
            return CompletedCommand(argv, 2, '', USAGE + '\n')
    try:
        b = dds.connect(domain, False if lan else None)
    except (dds.ConfigError, dds.ConnectError) as e:
        return CompletedCommand(argv, 1, '', f'{e}\n')
    dds.settle_discovery()
    reach = 'the local network' if b.localhost is False else 'this computer only'
    return CompletedCommand(argv, 0, f'joined DDS domain {b.domain_id} ({reach})\n', '')
