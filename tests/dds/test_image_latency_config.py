"""The Cyclone DDS settings that decide how fast a lost fragment of a large sample is
repaired (issue 19: 640x480 frames between labkit processes stalled ~200 ms a loss).

Structural, not timed: what labkit asks for, and what Cyclone itself says it applied
(its `config` trace lists every effective setting). The latencies these settings give
are measured by benchmarks/bench_dds.py (`--only image`), never asserted here.
"""
import re
import subprocess
import sys
import textwrap

import pytest

from labkit.dds import config

pytest.importorskip("cyclonedds")


def _effective(xml, tmp_path):
    """Cyclone's own report of the settings a domain made from `xml` runs with."""
    log = tmp_path / "cyclone-config.log"
    xml = xml.replace("<Tracing><Verbosity>none</Verbosity></Tracing>",
                      f"<Tracing><Category>config</Category>"
                      f"<OutputFile>{log}</OutputFile></Tracing>")
    assert str(log) in xml
    code = textwrap.dedent("""
        import sys
        from cyclonedds.domain import Domain
        Domain(int(sys.argv[1]), sys.argv[2])
    """)
    # a domain of its own, no participant: nothing is sent, only the configuration read
    subprocess.run([sys.executable, "-c", code, "231", xml], check=True, timeout=60)
    found = {}
    for line in log.read_text(encoding="utf-8").splitlines():
        m = re.search(r"config: Domain/(\S+): (.*?) \{", line)
        if m:
            found[m.group(1)] = m.group(2)
    return found


def test_loopback_writers_heartbeat_every_5_ms_while_a_reader_lacks_data(tmp_path):
    """The burst bound (for Fast DDS readers) makes labkit -> labkit frames go NACK by
    NACK; a NACK that races the first burst gets its fragments without a heartbeat, and
    the rest waited for Cyclone's 100 ms periodic heartbeat. On loopback it is 5 ms, and
    Cyclone's 20 ms floor (minsched) is lowered so that 5 ms holds."""
    got = _effective(config.cyclone_xml(True), tmp_path)
    assert got["Internal/HeartbeatInterval/#text"] == "5 ms"
    assert got["Internal/HeartbeatInterval[@minsched]"] == "2 ms"
    assert got["Internal/HeartbeatInterval[@min]"] == "1 ms"
    assert got["Internal/NackDelay/#text"] == "5 ms"
    # ... and the burst bound a Fast DDS reader needs is still there
    assert got["Internal/BurstSize/MaxRexmit/#text"] == f"{212992 * 2 // 3} B"
    assert got["Internal/BurstSize/MaxInitTransmit/#text"] == "0"


def test_a_lan_keeps_cyclones_heartbeats_and_whole_samples(tmp_path):
    """Off loopback nothing bounds bursts (the wire paces the sender), so nothing races
    a first burst: Cyclone's own heartbeat schedule stays. (No domain is made with the
    LAN configuration: it would open sockets off loopback. Cyclone's defaults are read
    from the loopback one without labkit's heartbeat element.)"""
    xml = config.cyclone_xml(False)
    assert "HeartbeatInterval" not in xml and "BurstSize" not in xml
    assert "<NackDelay>5ms</NackDelay>" in xml
    loopback = re.sub(r"<HeartbeatInterval[^>]*>[^<]*</HeartbeatInterval>", "",
                      config.cyclone_xml(True))
    got = _effective(loopback, tmp_path)
    assert got["Internal/HeartbeatInterval/#text"] == "100 ms"
    assert got["Internal/HeartbeatInterval[@minsched]"] == "20 ms"


def test_the_heartbeat_setting_appears_once_inside_internal():
    xml = config.cyclone_xml(True)
    assert xml.count("<HeartbeatInterval") == 1
    assert xml.index("<Internal>") < xml.index("<HeartbeatInterval") < xml.index("</Internal>")
