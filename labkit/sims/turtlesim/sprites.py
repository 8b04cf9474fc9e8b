"""Turtle pictures of our own drawing (not ROS's images), made with Pillow on first use.

Each sprite is 45x45 RGBA (one turtlesim metre), the turtle facing +x (right),
so a turtle with heading theta is drawn rotated by theta counter-clockwise.
Nine shell colours stand in for turtlesim's nine distribution turtles.
"""
from functools import lru_cache

from PIL import Image, ImageDraw

SIZE = 45
_SCALE = 4                                   # draw large, then shrink: smooth edges
SHELLS = [                                   # (shell, pattern) colours
    ((46, 139, 87), (102, 187, 106)),
    ((34, 120, 60), (129, 199, 132)),
    ((85, 139, 47), (156, 204, 101)),
    ((0, 121, 107), (77, 182, 172)),
    ((56, 142, 60), (200, 230, 120)),
    ((27, 94, 32), (102, 160, 80)),
    ((104, 159, 56), (220, 231, 117)),
    ((46, 125, 50), (165, 214, 167)),
    ((67, 160, 71), (255, 213, 79)),
]
SKIN = (156, 204, 101)
OUTLINE = (20, 60, 20)


@lru_cache(maxsize=None)
def sprite(index=0):
    """The RGBA Pillow image of turtle look `index` (0..8), facing right."""
    shell, pattern = SHELLS[index % len(SHELLS)]
    n = SIZE * _SCALE
    img = Image.new("RGBA", (n, n), (0, 0, 0, 0))
    d = ImageDraw.Draw(img)
    c = n / 2
    u = n / 45.0                             # one sprite pixel in drawing units
    line = max(1, round(1.2 * u))

    def ellipse(cx, cy, rx, ry, fill):
        d.ellipse((cx - rx, cy - ry, cx + rx, cy + ry), fill=fill, outline=OUTLINE, width=line)

    for sx in (-1, 1):                       # four flippers
        for sy in (-1, 1):
            ellipse(c + sx * 8 * u, c + sy * 11.5 * u, 4.5 * u, 3.5 * u, SKIN)
    d.polygon([(c - 14 * u, c - 2.5 * u), (c - 20 * u, c), (c - 14 * u, c + 2.5 * u)],
              fill=SKIN, outline=OUTLINE)    # tail
    ellipse(c + 15.5 * u, c, 5.5 * u, 4.5 * u, SKIN)   # head
    for sy in (-1, 1):                       # eyes
        d.ellipse((c + 17 * u - 1.2 * u, c + sy * 2 * u - 1.2 * u,
                   c + 17 * u + 1.2 * u, c + sy * 2 * u + 1.2 * u), fill=(10, 10, 10))
    ellipse(c - 1 * u, c, 12.5 * u, 10.5 * u, shell)   # shell
    # the shell's plates: a centre hexagon and a ring of smaller patches
    hexagon = [(c - 1 * u + 4.5 * u * dx, c + 4.2 * u * dy) for dx, dy in
               ((1, 0), (0.5, 0.87), (-0.5, 0.87), (-1, 0), (-0.5, -0.87), (0.5, -0.87))]
    d.polygon(hexagon, fill=pattern, outline=OUTLINE)
    for dx, dy in ((8, 0), (-10, 0), (3.5, 6.8), (3.5, -6.8), (-5.5, 6.8), (-5.5, -6.8)):
        ellipse(c - 1 * u + dx * u, c + dy * u, 2.1 * u, 1.8 * u, pattern)
    return img.resize((SIZE, SIZE), Image.LANCZOS)


@lru_cache(maxsize=None)
def sprite_png(index=0):
    """The same picture as PNG bytes (for browser-side drawing)."""
    import io
    buf = io.BytesIO()
    sprite(index).save(buf, format="PNG")
    return buf.getvalue()


@lru_cache(maxsize=4096)
def rotated(index, degrees):
    """The sprite turned `degrees` counter-clockwise (whole degrees are plenty), still RGBA.

    The result is larger than 45x45 (expand=True); its centre is the turtle's position.
    """
    return sprite(index).rotate(degrees, resample=Image.BICUBIC, expand=True)
