"""The sockets Cyclone DDS opens for this process: kept on loopback in localhost mode.

Cyclone DDS 11.0.1 binds its two unicast receive sockets (discovery and data) to the
wildcard address whichever interface it is configured for: ddsi_init.c asks for them
without an interface and ddsi_udp.c binds every receive socket to INADDR_ANY (in6addr_any
for IPv6); its configuration has no element that changes this (Interfaces/NetworkInterface
chooses what is advertised and sent on). Its transmit socket is bound to the interface's
address (127.0.0.1 here) already.

So, in localhost mode, labkit binds the wildcard sockets to the loopback *device*
(SO_BINDTODEVICE, which any user may set since Linux 5.7): the kernel then hands them
only datagrams that arrived on loopback, that is, sent from this machine, and routes
whatever they send through loopback. `ss -uanp` shows them as 0.0.0.0%lo:<port>. It
is done only when every address Cyclone bound is a loopback address (a CYCLONEDDS_URI
that picks a real interface is left alone), and never in LAN mode.

Every socket Cyclone opens is also made close-on-exec (Cyclone does not ask for it), so
a program that a labkit process starts does not inherit and hold DDS ports.
"""
import ipaddress
import os
import socket

from labkit import oslayer


def open_sockets(pid="self"):
    """{fd: inode} of the sockets of this process (or `pid`); {} where /proc is not there."""
    found, fds = {}, f"/proc/{pid}/fd"
    try:
        names = os.listdir(fds)
    except OSError:
        return found
    for name in names:
        try:
            target = os.readlink(os.path.join(fds, name))
        except OSError:
            continue
        if target.startswith("socket:["):
            found[int(name)] = target[8:-1]
    return found


def _is_loopback(host):
    return ipaddress.ip_address(host.split("%")[0]).is_loopback


def confine(before, loopback, device=oslayer.LOOPBACK_DEVICE):
    """Handle the sockets opened since `before` (an `open_sockets()` result): all are
    made close-on-exec; with `loopback`, the UDP ones bound to the wildcard address are
    bound to `device`. Returns the (host, port) of the sockets bound to it. Linux only
    (oslayer.SOCKETS_CONFINABLE): elsewhere there is no /proc to list them and no
    SO_BINDTODEVICE, and this returns []."""
    wildcard, specific = [], []
    for fd, inode in open_sockets().items():
        if before.get(fd) == inode:
            continue
        try:
            os.set_inheritable(fd, False)
            sock = socket.socket(fileno=os.dup(fd))
        except OSError:
            continue
        with sock:
            if sock.family not in (socket.AF_INET, socket.AF_INET6) \
                    or sock.type != socket.SOCK_DGRAM:
                continue
            host, port = sock.getsockname()[:2]
        if ipaddress.ip_address(host).is_unspecified:
            wildcard.append((fd, host, port))
        else:
            specific.append(host)
    if not loopback or device is None or not hasattr(socket, "SO_BINDTODEVICE") \
            or not all(_is_loopback(host) for host in specific):
        return []
    bound = []
    for fd, host, port in wildcard:
        with socket.socket(fileno=os.dup(fd)) as sock:
            try:
                sock.setsockopt(socket.SOL_SOCKET, socket.SO_BINDTODEVICE, device.encode())
            except OSError:       # Linux before 5.7 lets only CAP_NET_RAW do it
                continue
        bound.append((host, port))
    return bound
