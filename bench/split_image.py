"""Joins two images of one size as a split view: the left half of the first, the right half of
the second, a thin line between. For the README's with/without-AO picture
(bench/readme-images.sh).

    python3 bench/split_image.py LEFT.png RIGHT.png OUT.png
"""

import sys

from PIL import Image, ImageDraw


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: python3 bench/split_image.py LEFT.png RIGHT.png OUT.png")
    left, right = (Image.open(p).convert("RGB") for p in sys.argv[1:3])
    if left.size != right.size:
        sys.exit(f"the images differ in size: {left.size} and {right.size}")
    width, height = left.size
    middle = width // 2
    out = right.copy()
    out.paste(left.crop((0, 0, middle, height)), (0, 0))
    ImageDraw.Draw(out).line([(middle, 0), (middle, height)], fill=(255, 255, 255), width=2)
    out.save(sys.argv[3])


if __name__ == "__main__":
    main()
