"""Every socket a labkit process opens on DDS is on loopback unless the user asks for
the LAN, seen from outside the process: /proc/<pid>/fd (which sockets it holds, and
their close-on-exec flag), the kernel's socket table through sock_diag (addresses and
the device a socket is bound to, as `ss` reads them), and the SPDP announcement the
participant sends (the locators it tells peers to send to)."""
import os
import select
import socket
import struct
import subprocess
import sys
import textwrap
import time

from labkit.dds import sockets
from tests.dds.test_real_peers import REPO, _env, domain, finish, labkit  # noqa: F401

O_CLOEXEC = 0o2000000
SPDP_WRITER = b"\x00\x01\x00\xc2"


def _fd_flags(pid, fd):
    with open(f"/proc/{pid}/fdinfo/{fd}") as f:
        return int(next(line for line in f if line.startswith("flags:")).split()[1], 8)


def _kernel_inet_sockets():
    """{inode: (proto, (host, port), (host, port), bound device index)} of every TCP and
    UDP socket of this network namespace, from NETLINK_SOCK_DIAG (what `ss` reads)."""
    table = {}
    for family in (socket.AF_INET, socket.AF_INET6):
        for proto, pname in ((socket.IPPROTO_UDP, "udp"), (socket.IPPROTO_TCP, "tcp")):
            req = struct.pack("=BBBBI48x", family, proto, 0, 0, 0xFFFFFFFF)
            msg = struct.pack("=IHHII", 16 + len(req), 20, 0x301, 1, 0) + req
            with socket.socket(socket.AF_NETLINK, socket.SOCK_RAW, 4) as nl:   # SOCK_DIAG
                nl.sendto(msg, (0, 0))
                done = False
                while not done:
                    data = nl.recv(1 << 16)
                    at = 0
                    while at + 16 <= len(data):
                        length, kind = struct.unpack_from("=IH", data, at)
                        if kind in (2, 3):      # NLMSG_ERROR, NLMSG_DONE
                            done = True
                            break
                        body = data[at + 16:at + length]
                        fam = body[0]
                        sport, dport = struct.unpack_from(">HH", body, 4)
                        size = 4 if fam == socket.AF_INET else 16
                        src = socket.inet_ntop(fam, body[8:8 + size])
                        dst = socket.inet_ntop(fam, body[24:24 + size])
                        dev, = struct.unpack_from("=I", body, 40)
                        inode, = struct.unpack_from("=I", body, 68)
                        table[inode] = (pname, (src, sport), (dst, dport), dev)
                        at += (length + 3) & ~3
    return table


def _spdp_locators(datagram):
    """The unicast and multicast locators (kind, host, port) of an SPDP announcement."""
    assert datagram[:4] == b"RTPS", datagram[:20]
    at, found = 20, {}
    while at + 4 <= len(datagram):
        sub, flags = datagram[at], datagram[at + 1]
        end = "<" if flags & 1 else ">"
        length, = struct.unpack_from(end + "H", datagram, at + 2)
        body = datagram[at + 4:at + 4 + length]
        at += 4 + length
        if sub != 0x15 or body[8:12] != SPDP_WRITER:       # DATA of the SPDP writer
            continue
        to_qos, = struct.unpack_from(end + "H", body, 2)
        payload = body[4 + to_qos:]
        pend = "<" if payload[1] & 1 else ">"             # PL_CDR_LE / PL_CDR_BE
        p = 4
        while p + 4 <= len(payload):
            pid, plen = struct.unpack_from(pend + "HH", payload, p)
            if pid == 1:                                  # PID_SENTINEL
                break
            if pid in (0x31, 0x32, 0x33, 0x48):           # default/metatraffic uc/mc
                kind, port = struct.unpack_from(pend + "iI", payload, p + 4)
                addr = payload[p + 12:p + 28]
                host = socket.inet_ntop(socket.AF_INET, addr[12:]) if kind == 1 \
                    else socket.inet_ntop(socket.AF_INET6, addr)
                found.setdefault(pid, []).append((kind, host, port))
            p += 4 + plen
    return found


def _is_loopback(host):
    return host.startswith("127.") or host == "::1" or host.startswith("::ffff:127.")


def _joined_sockets(pid, longest=10.0):
    """The process's sockets, flags and the kernel's view of them, once its DDS join has
    opened them and bound the wildcard ones to the loopback device (or `longest` passed)."""
    lo = socket.if_nametoindex("lo")
    end = time.monotonic() + longest
    while True:
        held = {int(ino): fd for fd, ino in sockets.open_sockets(pid).items()}
        flags = {inode: _fd_flags(pid, fd) for inode, fd in held.items()}
        kernel = _kernel_inet_sockets()
        wildcard = [kernel[i] for i in held
                    if i in kernel and kernel[i][1][0] in ("0.0.0.0", "::")]
        if (held and len(wildcard) >= 2 and all(k[3] == lo for k in wildcard)) \
                or time.monotonic() > end:
            return held, flags, kernel
        time.sleep(0.05)


def test_every_socket_labkit_opens_is_on_loopback(tmp_path, domain):
    """The process's sockets are exactly Cyclone's: UDP only, each bound to a loopback
    address or, for the two unicast receive sockets Cyclone 11.0.1 binds to the wildcard
    address, to the loopback device; all close-on-exec. Its SPDP announcement reaches a
    peer from 127.0.0.1 and advertises only 127.0.0.1, on exactly those two ports."""
    base = 7400 + 250 * domain + 10
    # a peer that holds participant index 0's discovery port: labkit takes index 1, and
    # (Peer 127.0.0.1) announces itself to index 0's port, that is to this socket
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as peer:
        peer.bind(("127.0.0.1", base))
        prog = labkit(tmp_path, "sockets", """
            from std_msgs.msg import String
            rclpy.init()
            node = rclpy.create_node('sockets')
            node.create_publisher(String, 'chatter', 10).publish(String(data='x'))
            print('up', flush=True)
            spin_until(node, lambda: os.path.exists(DONE), 30)   # until the test has looked
        """.replace("DONE", repr(str(tmp_path / "done"))), domain)
        try:
            assert prog.stdout.readline().strip() == "up"
            spdp = None
            while spdp is None and select.select([peer], [], [], 15)[0]:
                data, sender = peer.recvfrom(1 << 16)
                locators = _spdp_locators(data)
                if locators:
                    spdp = locators
            # labkit exec joins DDS in the background once the first node exists (Humble's
            # rmw makes the participant with it): look once its sockets are confined
            held, flags, kernel = _joined_sockets(prog.pid)
        finally:
            (tmp_path / "done").touch()
            finish(prog)
    assert held, "labkit exec opened no sockets: it did not join DDS"
    assert spdp is not None, "no SPDP announcement reached 127.0.0.1"
    assert _is_loopback(sender[0]), sender

    lo = socket.if_nametoindex("lo")
    wildcard = set()
    for inode in held:
        assert inode in kernel, f"socket {inode} is not a TCP or UDP socket"
        proto, local, remote, dev = kernel[inode]
        assert proto == "udp", kernel[inode]
        assert flags[inode] & O_CLOEXEC, f"socket {inode} is inherited by child processes"
        if remote[1]:
            assert _is_loopback(remote[0]), kernel[inode]
        if local[0] in ("0.0.0.0", "::"):
            assert dev == lo, f"{local} is bound to the wildcard address on every device"
            wildcard.add(local[1])
        else:
            assert _is_loopback(local[0]), kernel[inode]

    assert set(spdp) == {0x31, 0x32}, f"multicast locators advertised: {spdp}"
    advertised = {loc for locs in spdp.values() for loc in locs}
    assert all(kind == 1 and host == "127.0.0.1" for kind, host, _ in advertised), advertised
    assert {port for _, _, port in advertised} == {base + 2, base + 3}, advertised
    assert wildcard == {base + 2, base + 3}, wildcard


def test_lan_mode_leaves_cyclones_sockets_on_every_device(domain):
    """localhost_only=False does not bind them to the loopback device (here Cyclone is
    still configured for loopback, so that the test sends nothing off this machine)."""
    code = textwrap.dedent("""
        import os, socket
        import labkit
        from labkit.dds import config
        loopback_xml = config.cyclone_xml
        config.cyclone_xml = lambda localhost=True: loopback_xml(True)
        labkit.set_time_mode('live')
        bridge = labkit.connect(localhost_only=False)
        devices = []
        for fd in sorted(os.listdir('/proc/self/fd')):
            try:
                sock = socket.socket(fileno=os.dup(int(fd)))
            except OSError:
                continue
            with sock:
                if sock.type == socket.SOCK_DGRAM:
                    dev = sock.getsockopt(socket.SOL_SOCKET, socket.SO_BINDTODEVICE, 16)
                    devices.append((sock.getsockname()[0], dev.rstrip(b'\\0').decode()))
        print(bridge.localhost, bridge.loopback_sockets, sorted(devices))
        labkit.disconnect()
    """)
    env = _env(domain, LABKIT_TIME="live", PYTHONPATH=str(REPO))
    env.pop("LABKIT_DDS", None)
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         timeout=60)
    assert out.stdout.split("\n")[0] == ("False [] [('0.0.0.0', ''), ('0.0.0.0', ''), "
                                         "('127.0.0.1', '')]"), out


def test_confine_takes_only_the_new_wildcard_udp_sockets():
    """In-process: sockets opened before are left as they were; of the new ones, UDP on
    the wildcard address gets the loopback device, every one becomes close-on-exec; with
    loopback=False none gets a device."""
    def device(sock):
        return sock.getsockopt(socket.SOL_SOCKET, socket.SO_BINDTODEVICE, 16).rstrip(b"\0")

    def udp(host):
        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        sock = socket.socket(family, socket.SOCK_DGRAM)
        sock.bind((host, 0))
        sock.set_inheritable(True)
        return sock

    old = udp("0.0.0.0")
    before = sockets.open_sockets()
    new_any, new_any6, new_lo = udp("0.0.0.0"), udp("::"), udp("127.0.0.1")
    tcp = socket.socket()
    tcp.set_inheritable(True)
    try:
        bound = sockets.confine(before, loopback=True)
        assert sorted(bound) == sorted([("0.0.0.0", new_any.getsockname()[1]),
                                        ("::", new_any6.getsockname()[1])])
        assert device(new_any) == device(new_any6) == b"lo"
        assert device(old) == device(new_lo) == b""
        assert old.get_inheritable()
        assert not any(s.get_inheritable() for s in (new_any, new_any6, new_lo, tcp))

        before = sockets.open_sockets()
        lan = udp("0.0.0.0")
        assert sockets.confine(before, loopback=False) == []
        assert device(lan) == b"" and not lan.get_inheritable()
        lan.close()
    finally:
        for sock in (old, new_any, new_any6, new_lo, tcp):
            sock.close()
