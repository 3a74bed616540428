#!/usr/bin/env python3
"""Regenerates font.txt, the bitmap font the benchmark chart is labelled with.

One-off tool, not run by scripts/bench.sh: the chart must not depend on a font
being installed. It renders printable ASCII from DejaVu Sans (Debian package
fonts-dejavu-core; DejaVu fonts are free, see their licence) at 13 px with
Pillow and quantises the coverage to 4 levels: ' ' '.' '+' '#'.

Usage: python3 gen_font.py /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf > font.txt
"""
import sys

from PIL import Image, ImageDraw, ImageFont

font = ImageFont.truetype(sys.argv[1], 13)
ascent, descent = font.getmetrics()
height = ascent + descent
print(f"# DejaVu Sans 13px, 4 levels; cell height {height}, baseline {ascent}")
for code in range(32, 127):
    ch = chr(code)
    adv = max(1, round(font.getlength(ch)))
    img = Image.new("L", (adv + 4, height), 0)
    ImageDraw.Draw(img).text((1, 0), ch, font=font, fill=255)
    bbox = img.getbbox()
    # Keep the advance, but widen the cell if the ink overhangs it.
    right = max(adv + 1, bbox[2] if bbox else 0)
    print(f"glyph {code} {adv}")
    for y in range(height):
        row = ""
        for x in range(1, right):
            v = img.getpixel((x, y))
            row += " .+#"[min(3, (v + 42) // 85)]
        print("|" + row.rstrip() + "|" if row.strip() else "|")
