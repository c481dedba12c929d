#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Rewrites PNG figures in place as 256-colour images (Pillow's median cut,
no dithering): a plot's few colours survive, and the file is about a third of
matplotlib's RGBA. The figure scripts run it on what they draw, so that the
repository stays small. Debian's python3-pil (a dependency of
python3-matplotlib), hence /usr/bin/python3.

  compact_png.py FIGURE.png [...]
"""
import sys

from PIL import Image


def main(paths):
    if not paths:
        print(__doc__, file=sys.stderr)
        return 2
    for path in paths:
        with Image.open(path) as image:
            compact = image.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT,
                                                   dither=Image.Dither.NONE)
        compact.save(path, optimize=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
