#!/usr/bin/python3
"""Writes the small inputs of the README's Eikonal examples (run from this
directory; the files are committed, this records how they were made)."""
import math

# speed.pgm: 64 x 48 speed image, white (255) fast, a slow grey disc (64)
# and a black wall (0: an obstacle) with a gap.
W, H = 64, 48
rows = []
for r in range(H):  # the first row is the top of the image
    y = H - 1 - r
    row = []
    for x in range(W):
        v = 255
        if math.hypot(x - 40, y - 30) < 9:
            v = 64
        if x == 20 and not (10 <= y <= 16):
            v = 0
        row.append(v)
    rows.append(row)
with open("speed.pgm", "w") as f:
    f.write("P2\n# speed image for eikonal: white fast, grey slow, black wall\n%d %d\n255\n" % (W, H))
    for row in rows:
        f.write(" ".join(map(str, row)) + "\n")

# volume.txt: 16^3 speeds, 1 below z = 8 and 2 above (a two-layer medium);
# slices bottom first, separated by a blank line, each slice's first line
# its top row.
N = 16
with open("volume.txt", "w") as f:
    for k in range(N):
        v = "1" if k < 8 else "2"
        for j in range(N):
            f.write(" ".join([v] * N) + "\n")
        if k < N - 1:
            f.write("\n")

# wall.txt: 41 x 41 obstacle mask (1 = obstacle), a wall at x = 20 with a
# gap for 30 <= y <= 34.
M = 41
with open("wall.txt", "w") as f:
    for r in range(M):
        y = M - 1 - r
        f.write(" ".join("1" if x == 20 and not (30 <= y <= 34) else "0" for x in range(M)) + "\n")
