#!/usr/bin/env python3
"""Leaks and dark contacts in default bakes, texel by texel against a final-gather reference.

Generates small scenes where lightmappers leak (issue 48): a panel hung 1 cm under a ceiling, a
box standing on a floor, two rooms sharing one floor and ceiling polygon across a thick wall with
the light in one of them. Bakes each by default (`radiosity bake SCENE`), then again from the same
solution with a per-texel final gather (`bake --solution DIR --gather N`: N cosine rays and N
shadow rays at every texel, the estimate the issue found right where the interpolated texels
leak) in the same layout (both from one `solve`), and compares the two lightmap.exr pages texel by texel:

- dark texels: the reference below 1% of the scene's mean lit texel; `leaks` is the share of them
  the bake shows above that 1% plus twice the reference, `worst_leak` the brightest of them as a
  share of the mean;
- lit texels: `too_dark` is the share the bake shows below half the reference, beyond 3 standard
  errors of the reference (its `error` channel), `worst_dark` the lowest bake / reference ratio.

    python3 bench/leak_suite.py [--gather 64] [--work /tmp/leak_suite] [--csv FILE]

Needs build/bin/radiosity and oiiotool (Debian's openimageio-tools, which scripts/setup.sh
installs). Prints one line per scene and writes the CSV (default bench/results/leak_suite.csv).
"""
import argparse, csv, os, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RADIOSITY = os.path.join(ROOT, "build", "bin", "radiosity")


class Obj:
    """An OBJ under construction: quads with a material each."""

    def __init__(self):
        self.vertices, self.faces = [], []

    def quad(self, corners, material):
        base = len(self.vertices) + 1
        self.vertices += corners
        self.faces.append((material, [base, base + 1, base + 2, base + 3]))

    def box(self, lo, hi, material, bottom=True):
        """A closed one-sided box looking out; without its bottom when it stands on a floor."""
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        self.quad([(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)], material)  # +y
        if bottom:
            self.quad([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], material)
        self.quad([(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)], material)  # -z
        self.quad([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], material)  # +z
        self.quad([(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], material)  # -x
        self.quad([(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)], material)  # +x

    def room(self, w, h, d, material):
        """Floor, ceiling and four walls of [0, w] × [0, h] × [0, d], looking in."""
        self.quad([(0, 0, 0), (0, 0, d), (w, 0, d), (w, 0, 0)], material)
        self.quad([(0, h, 0), (w, h, 0), (w, h, d), (0, h, d)], material)
        self.quad([(0, 0, 0), (w, 0, 0), (w, h, 0), (0, h, 0)], material)
        self.quad([(0, 0, d), (0, h, d), (w, h, d), (w, 0, d)], material)
        self.quad([(0, 0, 0), (0, h, 0), (0, h, d), (0, 0, d)], material)
        self.quad([(w, 0, 0), (w, 0, d), (w, h, d), (w, h, 0)], material)

    def panel(self, x0, x1, z0, z1, y, material):
        """A one-sided emitter facing down."""
        self.quad([(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)], material)

    def write(self, directory, name):
        os.makedirs(directory, exist_ok=True)
        with open(os.path.join(directory, name + ".mtl"), "w") as f:
            f.write("newmtl wall\nKd 0.7 0.7 0.7\nnewmtl box\nKd 0.5 0.5 0.5\n"
                    "newmtl panel\nKd 0 0 0\nKe 2 2 2\n")
        path = os.path.join(directory, name + ".obj")
        with open(path, "w") as f:
            f.write("mtllib %s.mtl\n" % name)
            for v in self.vertices:
                f.write("v %.9g %.9g %.9g\n" % v)
            current = None
            for material, face in self.faces:
                if material != current:
                    f.write("usemtl %s\n" % material)
                    current = material
                f.write("f %s\n" % " ".join(map(str, face)))
        return path


def panel_under_ceiling():
    o = Obj()
    o.room(4, 3, 4, "wall")
    o.panel(1, 3, 1, 3, 2.99, "panel")  # 1 cm under the ceiling
    return o


def box_on_floor():
    o = Obj()
    o.room(4, 3, 4, "wall")
    o.panel(1.5, 2.5, 1.5, 2.5, 2.999, "panel")
    o.box((0.8, 0, 1.2), (1.8, 0.9, 2.0), "box", bottom=False)
    return o


def wall_between_rooms():
    # One floor and one ceiling polygon under two rooms; a 10 cm wall between them, the light in
    # the first room only.
    o = Obj()
    o.room(8, 3, 4, "wall")
    o.box((3.95, 0, -0.001), (4.05, 3, 4.001), "wall", bottom=False)
    o.panel(1.5, 2.5, 1.5, 2.5, 2.999, "panel")
    return o


SCENES = [("panel_under_ceiling", panel_under_ceiling), ("box_on_floor", box_on_floor),
          ("wall_between_rooms", wall_between_rooms)]


def run(arguments):
    subprocess.run([RADIOSITY] + arguments + ["-q"], check=True)


def read_exr(path):
    """{(x, y): (g, error_g)} from oiiotool's dump of the page (green channel: the walls are grey)."""
    text = subprocess.run(["oiiotool", "--dumpdata", path, "--info"], check=True,
                          capture_output=True, text=True).stdout
    texels = {}
    for line in text.splitlines():
        line = line.strip()
        if not line.startswith("Pixel ("):
            continue
        where, values = line[len("Pixel ("):].split("):")
        x, y = (int(v) for v in where.split(","))
        v = [float(t) for t in values.split()]
        texels[(x, y)] = (v[1], v[3] if len(v) > 3 else 0.0)
    return texels


def compare(bake, reference):
    covered = [k for k in reference if reference[k][0] > 0 or bake.get(k, (0, 0))[0] > 0]
    lit_values = [reference[k][0] for k in covered if reference[k][0] > 0]
    mean = sum(lit_values) / max(1, len(lit_values))
    dark = [k for k in covered if reference[k][0] < 0.01 * mean]
    lit = [k for k in covered if reference[k][0] >= 0.01 * mean]
    leaks = [k for k in dark if bake[k][0] > 0.01 * mean + 2 * reference[k][0]]
    too_dark = [k for k in lit
                if bake[k][0] < 0.5 * reference[k][0] - 3 * reference[k][1]]
    return {
        "texels": len(covered),
        "dark_texels": len(dark),
        "leaks": len(leaks) / max(1, len(dark)),
        "worst_leak": max((bake[k][0] / mean for k in dark), default=0.0),
        "lit_texels": len(lit),
        "too_dark": len(too_dark) / max(1, len(lit)),
        "worst_dark": min((bake[k][0] / reference[k][0] for k in lit), default=1.0),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--gather", type=int, default=64)
    parser.add_argument("--work", default="/tmp/leak_suite")
    parser.add_argument("--csv", default=os.path.join(ROOT, "bench", "results", "leak_suite.csv"))
    args = parser.parse_args()
    rows = []
    for name, make in SCENES:
        directory = os.path.join(args.work, name)
        scene = make().write(directory, name)
        solved, default, reference = (os.path.join(directory, d)
                                      for d in ("solution", "default", "reference"))
        run(["solve", scene, "--out", solved])  # the solution both bakes read
        start = time.time()
        run(["bake", scene, "--solution", solved, "--out", default])
        bake_seconds = time.time() - start
        start = time.time()
        run(["bake", scene, "--solution", solved, "--gather", str(args.gather), "--out", reference])
        row = {"scene": name, "gather": args.gather, "bake_s": round(bake_seconds, 2),
               "reference_s": round(time.time() - start, 2)}
        row.update(compare(read_exr(os.path.join(default, "lightmap.exr")),
                           read_exr(os.path.join(reference, "lightmap.exr"))))
        rows.append(row)
        print("%-22s dark texels %6d, leaking %.4f (worst %.3f of the mean); lit %6d, below half "
              "%.4f (worst ratio %.3f)" % (name, row["dark_texels"], row["leaks"], row["worst_leak"],
                                           row["lit_texels"], row["too_dark"], row["worst_dark"]))
        sys.stdout.flush()
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
