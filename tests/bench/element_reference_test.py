#!/usr/bin/env python3
"""bench/element_reference under a sun and a sky: an open floor (nothing above it) has, on every
element, B = ρ (E_sun cosθ + π L_sky) exactly. The sun's half-degree disc and the sky must both
be sampled at the element's own points: a cosine ray alone would leave through the disc about
once in 50,000 paths, and the reference would miss nearly all of the sunlight.

    python3 element_reference_test.py ELEMENT_REFERENCE WORK_DIR
"""
import csv
import json
import math
import os
import subprocess
import sys

RHO = (0.5, 0.4, 0.3)
SUN_DIRECTION = (1.0, -2.0, 0.5)  # the way the light travels
SUN_IRRADIANCE = (800.0, 780.0, 700.0)
SKY_RADIANCE = (0.3, 0.4, 0.6)
# The sky's two MIS-weighted halves are each exactly π L / 2 on an open floor; what noise is left
# is the cosine's spread over the sun's disc (half-angle 0.265°): a relative standard error near
# 2e-4 at 256 paths. Each value must lie within 5 of its standard errors of the exact one, and
# those must be small: a reference that finds the sun by chance has both a wrong mean and a large
# standard error.
SIGMAS = 5
MAX_RELATIVE_STANDARD_ERROR = 1e-3


def main():
    tool, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "floor.obj"), "w") as f:
        f.write("mtllib floor.mtl\nv -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nusemtl floor\nf 1 4 3 2\n")
    with open(os.path.join(work, "floor.mtl"), "w") as f:
        f.write("newmtl floor\nKd %g %g %g\n" % RHO)
    lights = os.path.join(work, "sun_and_sky.json")
    with open(lights, "w") as f:
        json.dump({"lights": [
            {"type": "directional", "direction": list(SUN_DIRECTION), "irradiance": list(SUN_IRRADIANCE),
             "angular_diameter_degrees": 0.53},
            {"type": "sky", "radiance": list(SKY_RADIANCE), "up": [0, 1, 0]}]}, f)
    out = os.path.join(work, "reference.csv")
    subprocess.run([tool, os.path.join(work, "floor.obj"), "--elements", "200", "--sample", "40", "--paths",
                    "256", "--threads", "1", "--lights", lights, "--out", out], check=True)
    cos_theta = -SUN_DIRECTION[1] / math.sqrt(sum(c * c for c in SUN_DIRECTION))
    expected = [r * (e * cos_theta + math.pi * l) for r, e, l in zip(RHO, SUN_IRRADIANCE, SKY_RADIANCE)]
    rows = list(csv.DictReader(open(out)))
    if len(rows) != 40:
        sys.exit(f"element_reference_test: {len(rows)} elements written, 40 asked for")
    worst_sigmas = worst_se = 0.0
    for row in rows:
        for c, want in zip("rgb", expected):
            se = float(row["se_" + c])
            worst_se = max(worst_se, se / want)
            worst_sigmas = max(worst_sigmas, abs(float(row["B_" + c]) - want) / max(se, 1e-9 * want))
    print(f"element_reference_test: worst deviation {worst_sigmas:.2f} standard errors, largest "
          f"relative standard error {worst_se:.2e}, over {len(rows)} elements "
          f"(expected B = {expected[0]:.4f} {expected[1]:.4f} {expected[2]:.4f})")
    if worst_sigmas > SIGMAS or worst_se > MAX_RELATIVE_STANDARD_ERROR:
        sys.exit(f"element_reference_test: beyond {SIGMAS} standard errors or a relative standard "
                 f"error above {MAX_RELATIVE_STANDARD_ERROR:g}")


if __name__ == "__main__":
    main()
