"""Live time: a process whose program sleeps with time.sleep() (a plain `while True:
...; time.sleep(1)` loop, no rclpy) ends when it is stopped, as Ctrl-C / SIGINT ends
the real program. It used to be left running for good, printing on, with returncode
-2 reported after a 2 s wait."""
import time

from labkit import process


def looping(args=None):
    while True:
        print("still here")
        time.sleep(0.2)


def test_stop_ends_a_process_that_sleeps_in_live_time(live):
    proc = process.start(main=looping, name="looping", echo=False)
    time.sleep(0.3)                   # the notebook itself: a real sleep
    assert proc.running
    proc.stop()
    assert not proc.thread.is_alive()
    assert proc.returncode == -2      # KeyboardInterrupt, as after SIGINT
