"""Print speed figures of labkit.interfaces (a plain script, not a test).

    .venv/bin/python tests/interfaces/tools/bench_interfaces.py
"""
import time
import timeit


def per_call_us(fn, number):
    return timeit.timeit(fn, number=number) / number * 1e6


def main():
    t0 = time.perf_counter()
    import labkit.interfaces as li
    t1 = time.perf_counter()
    li.get_type('std_msgs/msg/String')
    t2 = time.perf_counter()
    names = li.list_interfaces()
    for name in names:
        li.get_type(name)
    t3 = time.perf_counter()
    print('import labkit.interfaces (numpy included): %.1f ms' % ((t1 - t0) * 1e3))
    print('first class (std_msgs/msg/String): %.2f ms' % ((t2 - t1) * 1e3))
    print('generate all %d bundled interfaces: %.1f ms' % (len(names), (t3 - t2) * 1e3))

    Image = li.get_type('sensor_msgs/msg/Image')
    img = Image(height=480, width=640, encoding='bgr8', step=1920)
    img.data = bytes(640 * 480 * 3)
    print('copy_message Image 640x480 bgr8: %.1f us' % per_call_us(
        lambda: li.copy_message(img), 2000))
    print('serialize Image 640x480 bgr8: %.1f us' % per_call_us(lambda: li.serialize(img), 500))
    data = li.serialize(img)
    print('deserialize Image 640x480 bgr8: %.1f us' % per_call_us(
        lambda: li.deserialize(data, Image), 500))

    Twist = li.get_type('geometry_msgs/msg/Twist')
    tw = Twist()
    tw.linear.x = 2.0
    print('Twist(): %.2f us' % per_call_us(Twist, 100000))
    print('copy_message Twist: %.2f us' % per_call_us(lambda: li.copy_message(tw), 100000))
    li.serialize(tw)
    print('serialize Twist: %.2f us' % per_call_us(lambda: li.serialize(tw), 100000))
    data = li.serialize(tw)
    print('deserialize Twist: %.2f us' % per_call_us(lambda: li.deserialize(data, Twist), 100000))
    from labkit.interfaces.convert import message_to_yaml
    pose = li.get_type('turtlesim/msg/Pose')(x=5.5)
    print('message_to_yaml turtlesim Pose: %.1f us' % per_call_us(
        lambda: message_to_yaml(pose), 5000))


if __name__ == '__main__':
    main()
