"""A bar chart of frames per second over time, as an SVG the book's column shows at full size.

    svg = frame_rate_svg([(0, 10), (1, 10), ...], [(0, '0.1 秒'), (4, '0.5 秒'), ...])

`rates` are (second, frames in that second) pairs (FrameLog.rates()); `phases`
are (start second, label) pairs: each phase gets a shaded band with its label.
The picture is 720 px wide (the book's column) with labels of 13-14 px.
"""
from html import escape

WIDTH, HEIGHT = 720, 300
LEFT, RIGHT, TOP, BOTTOM = 60, 16, 34, 48
FONT = 'Noto Sans CJK SC, Microsoft YaHei, PingFang SC, DejaVu Sans, sans-serif'
BANDS = ('#eef3fa', '#fbf3e6')


def frame_rate_svg(rates, phases, *, title='每秒收到的帧数', y_label='帧/秒',
                   x_label='时间（秒）', band_title='timer_period ='):
    seconds = len(rates)
    top_value = max([n for _, n in rates] + [1])
    y_max = (top_value // 5 + 1) * 5      # headroom: the phase labels sit above the bars
    plot_w, plot_h = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM
    step = plot_w / max(seconds, 1)

    def x(t):
        return LEFT + t * step

    def y(v):
        return TOP + plot_h * (1 - v / y_max)

    parts = [f'<rect x="0" y="0" width="{WIDTH}" height="{HEIGHT}" fill="white"/>']
    ends = [start for start, _ in phases[1:]] + [seconds]
    for k, ((start, label), end) in enumerate(zip(phases, ends)):
        parts.append(f'<rect x="{x(start):.1f}" y="{TOP}" width="{x(end) - x(start):.1f}" '
                     f'height="{plot_h}" fill="{BANDS[k % 2]}"/>')
        parts.append(f'<text x="{(x(start) + x(end)) / 2:.1f}" y="{TOP + 20}" text-anchor="middle" '
                     f'font-size="13" fill="#333">{escape(band_title)} {escape(label)}</text>')
    for v in range(0, y_max + 1, 5):
        parts.append(f'<line x1="{LEFT}" y1="{y(v):.1f}" x2="{WIDTH - RIGHT}" y2="{y(v):.1f}" '
                     f'stroke="#ccc" stroke-width="1"/>')
        parts.append(f'<text x="{LEFT - 8}" y="{y(v) + 4:.1f}" text-anchor="end" font-size="13" '
                     f'fill="#333">{v}</text>')
    for t, n in rates:
        parts.append(f'<rect x="{x(t) + step * 0.15:.1f}" y="{y(n):.1f}" width="{step * 0.7:.1f}" '
                     f'height="{y(0) - y(n):.1f}" fill="#4a78b0"/>')
        if n:
            parts.append(f'<text x="{x(t) + step / 2:.1f}" y="{y(n) - 4:.1f}" text-anchor="middle" '
                         f'font-size="12" fill="#333">{n}</text>')
    for t in range(0, seconds + 1, 2):
        parts.append(f'<text x="{x(t):.1f}" y="{TOP + plot_h + 18}" text-anchor="middle" '
                     f'font-size="13" fill="#333">{t}</text>')
    parts.append(f'<line x1="{LEFT}" y1="{y(0):.1f}" x2="{WIDTH - RIGHT}" y2="{y(0):.1f}" '
                 f'stroke="#333" stroke-width="1"/>')
    parts.append(f'<text x="{LEFT + plot_w / 2:.1f}" y="{HEIGHT - 8}" text-anchor="middle" '
                 f'font-size="14" fill="#333">{escape(x_label)}</text>')
    parts.append(f'<text x="16" y="{TOP + plot_h / 2:.1f}" text-anchor="middle" font-size="14" '
                 f'fill="#333" transform="rotate(-90 16 {TOP + plot_h / 2:.1f})">{escape(y_label)}</text>')
    parts.append(f'<text x="{LEFT}" y="20" font-size="14" font-weight="bold" '
                 f'fill="#333">{escape(title)}</text>')
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
            f'viewBox="0 0 {WIDTH} {HEIGHT}" font-family="{FONT}">' + ''.join(parts) + '</svg>')
