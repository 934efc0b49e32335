#!/usr/bin/env python3
"""Rendering efficiency of this project against Mitsuba 3, in one run.

Efficiency is 1 / (MSE x render time) at equal samples per pixel. Both
renderers are unbiased (checked: the last column), so a render's MSE is its
variance, estimated without a reference from two (or `--seeds N`)
renders with different seeds: for independent estimates X1, X2 of the same image,

    E[(X1 - X2)^2] / 2 = Var[X]      (per pixel and channel, averaged)

which needs no converged reference and has no reference noise in it. With a
scrambled low-discrepancy sampler, different seeds are independent
randomisations, so the same identity holds. With `--seeds N` each renderer
renders N seeds and the variance is each pixel's sample variance over
them (`N - 1` degrees of freedom, the formula above for N = 2): where a
scene's error is a few rare samples of huge value (a sun seen through
glass), two renders say little about it, and more seeds say more.
`--spikes VALUE` then reports where such samples are: the render pixels
(a seed's pixel) whose excess over the renders' median there, times the
samples per pixel, is above VALUE (the value one sample would need to
explain it), the pixels they are in, those pixels' share of the
variance, and how many of those pixels both renderers share.

Each renderer runs its own default estimator at the same samples per
pixel: Mitsuba's path tracer one emitter sample a vertex, this project
the render plan's (one sample a vertex of each light in the scene, four
of an environment map: `plan::light_samples`). `-- -l 1` after the
options gives every light of ours one sample, as the course's `-l 1`.

For each scene and repetition: this project renders each seed (`--seed 0`,
`--seed 1`, ...; time from its `render: S s` line, which excludes loading
and the BVH build), then Mitsuba renders the same seeds in one process
(`benches/compare/mitsuba_timed.py`; times of the renders after the
first, whose kernels are compiled). Times are medians over repetitions
and seeds; the machine is shared, so only ratios from one run mean
anything.

The emitters' own pixels are a small part of the image but can hold most
of its squared error (the light's edge pixels, with a random position in
the pixel, are lit or not); the course's scenes show the light as their
emissive quad, Mitsuba as the light's rectangle. So the table also gives
the efficiency over the pixels whose mean luminance is below 1 in both
renders (the emitters left out), and compares the two renderers' mean
radiance over those pixels (the last column: both are unbiased). The
luminance is each render's median over the pixel and its 8 neighbours:
an emitter is a region and keeps its pixels, while a firefly, one pixel
that noise lifts above 1, would otherwise take that pixel out of the
mask and with it the firefly's share of its renderer's error and mean
(docs/10-performance.md: the held-out map).

Needs Python with numpy and mitsuba (a venv: `pip install mitsuba numpy`,
and `apt-get install -y libllvm19`), the Mitsuba tool
`../shared/tools/mitsuba/dae_reference.py` (outside this repository; a
version with `--each`, which writes each seed's render), and
`cargo build --release`. The environment maps are looked for in `--maps`
(default: the current directory); the project makes its own (the error
says how): the studio map, and outdoor skies with a sun (`sky-2k.hdr`,
`sun-2k.hdr` with the real sun's size, `sun-4k-black.hdr` black below the
horizon).

A scene may change the course's file (a copy written to `--out` before
rendering; the course's file is not changed): the copper bunny is
`bunny_unlit.dae` with its bunny made a rough copper conductor (the
smooth copper bunny: the same copper near a mirror, `alpha` 0.05),
`CBbunny_mirror`, `CBbunny_glass` and `CBbunny_copper` CBbunny's bunny
made a mirror, glass or that copper, `CBbunny_257k` its triangles each
cut into nine (the issue ran it at 16 spp: `--spp 16`).

    python3 benches/compare/efficiency.py [--reps 3] [--only CBbunny ...] [-- EXTRA PATHTRACER FLAGS]
    python3 benches/compare/efficiency.py --scene FILE.dae --depth 5 [--env MAP.hdr]   # any scene, any map
    python3 benches/compare/efficiency.py --seeds 8 ...   # variance from 8 renders of each renderer
    python3 benches/compare/efficiency.py --seeds 8 --spikes 3e4 ...   # and where rare huge samples make it
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


def with_material(effect, material):
    """Writes a copy of a scene whose effect `effect` carries
    `material` (a CGL `<extra>`), put after the effect's `profile_COMMON`."""
    def make(scene, path):
        with open(scene) as f:
            text = f.read()
        start = text.index(f'<effect id="{effect}"')
        end = text.index("</profile_COMMON>", start) + len("</profile_COMMON>")
        with open(path, "w") as f:
            f.write(text[:end] + material + text[end:])
    return make


def subdivided(geometry, n):
    """Writes a copy of a scene whose mesh `geometry` (a triangle
    `<polylist>` with a VERTEX and a NORMAL input) has each triangle cut
    into n^2 in its plane: the points (i A + j B + k C) / n, i + j + k = n,
    the normals interpolated the same way and normalised (neither renderer
    reads them: both rebuild normals from connectivity). A point is keyed
    by its weights on the original vertices' indices, so the triangles on
    either side of an edge share its new vertices bit for bit (the mesh
    stays watertight), and the surface is the original one."""
    def make(scene, path):
        with open(scene) as f:
            text = f.read()
        start = text.index(f'<geometry id="{geometry}"')
        end = text.index("</geometry>", start)
        mesh = text[start:end]
        arrays = re.findall(r'<float_array id="([^"]+)" count="\d+">([^<]*)</float_array>', mesh)
        floats = {name: [float(x) for x in values.split()] for name, values in arrays}
        positions = floats[f"{geometry}-positions-array"]
        normals = floats[f"{geometry}-normals-array"]
        # What this rewrite assumes, checked: one list of triangles whose
        # corners are (vertex, normal) index pairs.
        assert mesh.count("<polylist") == 1 and mesh.count("<p>") == 1, f"{geometry}: one <polylist>"
        assert len(re.findall(r"<input [^>]*offset=", mesh)) == 2, f"{geometry}: VERTEX and NORMAL only"
        vcount = re.search(r"<vcount>([^<]*)</vcount>", mesh).group(1).split()
        assert set(vcount) == {"3"}, f"{geometry}: triangles only"
        corners = [int(x) for x in re.search(r"<p>([^<]*)</p>", mesh).group(1).split()]
        assert len(corners) == 6 * len(vcount)
        faces = []

        def point_table(source, normalise):
            """Returns `index(weights)`, the index of the point sum(w v) / n
            of `source`'s rows v for (row, integer weight) pairs (made on
            its first request), and the list of the points made."""
            made, index_of = [], {}

            def index(weights):
                key = tuple(sorted((v, w) for v, w in weights if w))
                if key not in index_of:
                    index_of[key] = len(made)
                    value = [sum(w * source[3 * v + a] for v, w in key) / n for a in range(3)]
                    norm = sum(c * c for c in value) ** 0.5 if normalise else 0
                    if norm > 0:
                        value = [c / norm for c in value]
                    made.append(value)
                return index_of[key]
            return index, made

        new_point, new_points = point_table(positions, False)
        new_normal, new_normals = point_table(normals, True)
        for f in range(len(corners) // 6):
            vs = corners[6 * f:6 * f + 6:2]
            ns = corners[6 * f + 1:6 * f + 6:2]

            def corner(i, j):
                weights = (i, j, n - i - j)
                return new_point(zip(vs, weights)), new_normal(zip(ns, weights))
            for i in range(n):
                for j in range(n - i):
                    faces.append((corner(i, j), corner(i + 1, j), corner(i, j + 1)))
                    if i + j < n - 1:
                        faces.append((corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)))

        def flat(rows):
            return " ".join(f"{x:.9g}" for row in rows for x in row)
        for kind, rows in (("positions", new_points), ("normals", new_normals)):
            mesh = re.sub(rf'(<float_array id="{geometry}-{kind}-array" count=")\d+(">)[^<]*',
                          lambda m: f"{m.group(1)}{3 * len(rows)}{m.group(2)}{flat(rows)}", mesh)
            mesh = re.sub(rf'(<source id="[^"]+-{kind}">.*?<accessor [^>]*count=")\d+',
                          lambda m: f"{m.group(1)}{len(rows)}", mesh, flags=re.S)
        mesh = re.sub(r'(<polylist [^>]*count=")\d+', lambda m: f"{m.group(1)}{len(faces)}", mesh)
        mesh = re.sub(r"<vcount>[^<]*</vcount>", "<vcount>" + " ".join(["3"] * len(faces))
                      + "</vcount>", mesh)
        mesh = re.sub(r"<p>[^<]*</p>", "<p>" + " ".join(
            f"{p} {q}" for face in faces for p, q in face) + "</p>", mesh)
        with open(path, "w") as f:
            f.write(text[:start] + mesh + text[end:])
    return make


# A rough copper (Beckmann, alpha 0.2; eta and k of copper at about
# 614 / 549 / 466 nm, as the course's own microfacet scenes give them per channel).
COPPER = """<extra><technique profile="CGL"><microfacet><alpha>0.2</alpha>
<eta>0.27105 0.67693 1.31640</eta><k>3.60920 2.62480 2.29210</k></microfacet></technique></extra>"""
# The same copper, near a mirror (alpha 0.05): sharper than a soft map.
SMOOTH_COPPER = COPPER.replace("<alpha>0.2</alpha>", "<alpha>0.05</alpha>")
# A perfect mirror, and the course's glass (CBspheres.dae's).
MIRROR = """<extra><technique profile="CGL"><mirror><reflectance>1 1 1</reflectance></mirror>
</technique></extra>"""
GLASS = """<extra><technique profile="CGL"><glass><reflectance>1 1 1</reflectance>
<transmittance>1 1 1</transmittance><roughness>0</roughness><ior>1.45</ior></glass></technique></extra>"""

# name: (course file, course depth -m, environment map or None,
#        a change to the file (`make(scene, path)` writes the changed copy) or None)
SCENES = {
    "CBspheres_lambertian": ("CBspheres_lambertian.dae", 8, None, None),
    "CBbunny": ("CBbunny.dae", 5, None, None),
    "CBspheres_microfacet_al_ag": ("CBspheres_microfacet_al_ag.dae", 5, None, None),
    "bunny_unlit+studio": ("bunny_unlit.dae", 5, "studio.hdr", None),
    # Not in the first four: checks on scenes no lever was tuned on
    # (`--only CBspheres teapot+studio`). CBempty is not among them: its
    # emissive ceiling mesh glows besides its point light, which this
    # project counts and the Mitsuba tool leaves out.
    "CBspheres": ("CBspheres.dae", 5, None, None),
    # Issue 24's own setting for it, `-m 8`: where roulette acts.
    "CBspheres_m8": ("CBspheres.dae", 8, None, None),
    "teapot+studio": ("teapot.dae", 5, "studio.hdr", None),
    # Outdoor maps the sampler was not tuned on (`environment_map --sky`).
    "copper_bunny+sky2k": ("bunny_unlit.dae", 5, "sky-2k.hdr", with_material("Default-effect", COPPER)),
    "copper_bunny+sun2k": ("bunny_unlit.dae", 5, "sun-2k.hdr", with_material("Default-effect", COPPER)),
    "copper_bunny+sun4k_black": ("bunny_unlit.dae", 5, "sun-4k-black.hdr",
                                 with_material("Default-effect", COPPER)),
    # A large mesh in the box (issue 24's "200k triangles", run at
    # `--spp 16`): CBbunny's 28,576 triangles each cut into 9, 257,184.
    "CBbunny_257k": ("CBbunny.dae", 5, None, subdivided("Mesh-mesh", 3)),
    # CBbunny with its bunny a mirror, glass or copper: run first as checks
    # that no lever was tuned on, they then decided which meshes are
    # caustic casters (docs/maintainers/caustic-casters.md).
    "CBbunny_mirror": ("CBbunny.dae", 5, None, with_material("Default-effect", MIRROR)),
    "CBbunny_glass": ("CBbunny.dae", 5, None, with_material("Default-effect", GLASS)),
    "CBbunny_copper": ("CBbunny.dae", 5, None, with_material("Default-effect", COPPER)),
    "teapot+sun2k": ("teapot.dae", 5, "sun-2k.hdr", None),
    # A near-mirror under a soft map and under a sun: held out at first;
    # the first (0.68) then decided where the map's samples are split
    # (plan::light_samples; docs/10, section 2).
    "smooth_copper_bunny+studio": ("bunny_unlit.dae", 5, "studio.hdr",
                                   with_material("Default-effect", SMOOTH_COPPER)),
    "smooth_copper_bunny+sun2k": ("bunny_unlit.dae", 5, "sun-2k.hdr",
                                  with_material("Default-effect", SMOOTH_COPPER)),
    # Mirror and glass under the maps: a sun's glints (glint samples,
    # docs/08-environment.md). The bunny's decided the allocation's rule;
    # the teapot's were held out, run once after it.
    **{f"{name}_bunny+{m}": ("bunny_unlit.dae", 5, f, with_material("Default-effect", mat))
       for name, mat in (("mirror", MIRROR), ("glass", GLASS))
       for m, f in (("studio", "studio.hdr"), ("sky2k", "sky-2k.hdr"), ("sun2k", "sun-2k.hdr"),
                    ("sun4k_black", "sun-4k-black.hdr"))},
    **{f"{name}_teapot+{m}": ("teapot.dae", 5, f, with_material("Default_007-effect", mat))
       for name, mat in (("mirror", MIRROR), ("glass", GLASS))
       for m, f in (("sun2k", "sun-2k.hdr"), ("sun4k_black", "sun-4k-black.hdr"))},
    # Held out: smaller maps, the real sun two texels of the 1k one and
    # between the 512-wide one's texel centres (so none), or a large sun
    # of a few texels (`sun-small`, 2 degrees at 256 x 128).
    **{f"{name}_bunny+{m}": ("bunny_unlit.dae", 5, f, with_material("Default-effect", mat))
       for name, mat in (("mirror", MIRROR), ("glass", GLASS), ("smooth_copper", SMOOTH_COPPER))
       for m, f in (("sun1k", "sun-1k.hdr"), ("sun512", "sun-512.hdr"),
                    ("sunsmall", "sun-small.hdr"))},
}
# The scenes run when neither --only nor --scene is given.
DEFAULT = ["CBspheres_lambertian", "CBbunny", "CBspheres_microfacet_al_ag", "bunny_unlit+studio",
           "copper_bunny+sky2k", "copper_bunny+sun2k"]
MAP_COMMANDS = {
    "studio.hdr": "--hdr studio.hdr",
    "sky-2k.hdr": "--sky sky-2k.hdr",
    "sun-2k.hdr": "--sky sun-2k.hdr --sun-degrees 0.27",
    "sun-4k-black.hdr": "--sky sun-4k-black.hdr --height 2048 --sun-degrees 0.27 --black-ground",
    "sun-1k.hdr": "--sky sun-1k.hdr --height 512 --sun-degrees 0.27",
    "sun-512.hdr": "--sky sun-512.hdr --height 256 --sun-degrees 0.27",
    "sun-small.hdr": "--sky sun-small.hdr --height 128 --sun-degrees 2",
}


def run(cmd, log):
    """Runs `cmd`, appends its output to `log`, returns stdout."""
    result = subprocess.run(cmd, capture_output=True, text=True)
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n" + result.stdout + result.stderr + "\n")
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(cmd)}\n{result.stderr}")
    return result.stdout


def read_rgb(path):
    import mitsuba as mi
    import numpy as np

    bitmap = mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32)
    return np.array(bitmap, dtype=np.float64)


def median_3x3(image):
    """Each pixel's median over itself and its 8 neighbours (edges repeated)."""
    import numpy as np

    padded = np.pad(image, 1, mode="edge")
    h, w = image.shape
    shifted = [padded[dy:dy + h, dx:dx + w] for dy in range(3) for dx in range(3)]
    return np.median(np.stack(shifted), axis=0)


def pixel_variances(images):
    """Each pixel's sample variance over independent renders of one image
    (for two, (a - b)^2 / 2), averaged over the channels."""
    import numpy as np

    return np.stack(images).var(0, ddof=1).mean(-1)


def variance(images, mask=None):
    """Per-render variance: `pixel_variances` averaged over the pixels of
    `mask` if given, else over all."""
    per_pixel = pixel_variances(images)
    return float(per_pixel.mean() if mask is None else per_pixel[mask].mean())


def spikes(images, spp, threshold):
    """Where single samples of huge value make a renderer's error: each
    render's pixel luminance minus the median of all the renders at that
    pixel, times `spp`, is the value one sample would need to explain the
    difference. Returns (how many render pixels exceed `threshold`, the
    mask of pixels where some render does, the share of the variance in
    those pixels)."""
    import numpy as np

    lum = luminance(np.stack(images))
    excess = (lum - np.median(lum, 0)) * spp
    over = excess > threshold
    pixels = over.any(0)
    per_pixel = pixel_variances(images)
    return int(over.sum()), pixels, float(per_pixel[pixels].sum() / per_pixel.sum())


def luminance(rgb):
    return rgb @ [0.2126, 0.7152, 0.0722]


def main():
    extra = []
    if "--" in sys.argv:
        cut = sys.argv.index("--")
        sys.argv, extra = sys.argv[:cut], sys.argv[cut + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scenes", default=os.environ.get("CS184_SCENES",
                    os.path.join(ROOT, "..", "shared", "scenes", "cs184")))
    ap.add_argument("--tool", default=os.path.join(ROOT, "..", "shared", "tools", "mitsuba",
                                                    "dae_reference.py"))
    ap.add_argument("--pathtracer", default=os.path.join(ROOT, "target", "release", "pathtracer"))
    ap.add_argument("--maps", default=".", help="where the environment maps are")
    ap.add_argument("--scene", help="any .dae scene, instead of the named ones")
    ap.add_argument("--depth", type=int, default=5, help="-m for --scene")
    ap.add_argument("--env", help="an environment map for --scene")
    ap.add_argument("--size", type=int, nargs=2, default=[480, 360])
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--seeds", type=int, default=2, help="renders of each renderer (at least 2)")
    ap.add_argument("--spikes", type=float, metavar="VALUE",
                    help="also report the render pixels (a seed's pixel) whose excess over the "
                         "renders' median there, times the samples per pixel, is above VALUE "
                         "(needs --seeds 3 or more), and the pixels both renderers share")
    ap.add_argument("--only", nargs="*", choices=sorted(SCENES))
    ap.add_argument("--out", default="efficiency-out")
    a = ap.parse_args()
    if a.seeds < 2:
        sys.exit("--seeds: at least 2 renders are needed for a variance")
    if a.spikes is not None and a.seeds < 3:
        sys.exit("--spikes: needs --seeds 3 or more (a median of two renders is their mean)")
    os.makedirs(a.out, exist_ok=True)
    log = os.path.join(a.out, "log.txt")
    w, h = a.size
    print(f"{w}x{h}, {a.spp} spp, -t {a.threads}, {a.reps} repetitions of {a.seeds} seeds; "
          f"our extra flags: {extra}")
    print("| scene | ours: time (s) | ours: MSE | Mitsuba: time (s) | Mitsuba: MSE "
          "| efficiency ours/Mitsuba | without emitters | mean ours/Mitsuba |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    if a.scene:
        SCENES["custom"] = (os.path.abspath(a.scene), a.depth, a.env and os.path.abspath(a.env), None)
    for name in ["custom"] if a.scene else a.only or DEFAULT:
        file, depth, env, change = SCENES[name]
        scene = os.path.join(a.scenes, file)
        if change:
            changed = os.path.join(a.out, f"{name}.dae")
            change(scene, changed)
            scene = changed
        if env:
            env = os.path.join(a.maps, env)
            if not os.path.exists(env):
                make = MAP_COMMANDS.get(os.path.basename(env), "...")
                sys.exit(f"{env} not found: cargo run --release --example environment_map -- {make}"
                         f" (in {a.maps})")
        ours_t, mi_t = [], []
        for rep in range(a.reps):
            images = []
            for seed in range(a.seeds):
                path = os.path.join(a.out, f"{name}-ours-{seed}.exr")
                cmd = [a.pathtracer, scene, "-r", str(w), str(h), "-s", str(a.spp),
                       "-m", str(depth), "-t", str(a.threads), "--seed", str(seed), "-f", path]
                cmd += ["-e", env] if env else []
                out = run(cmd + extra, log)
                ours_t.append(float(re.search(r"render: ([0-9.]+) s", out).group(1)))
                images.append(path)
            last = os.path.join(a.out, f"{name}-mitsuba-last.exr")
            each = os.path.join(a.out, f"{name}-mitsuba-")
            cmd = [sys.executable, os.path.join(HERE, "mitsuba_timed.py"), a.tool, last, "--",
                   scene, os.path.join(a.out, f"{name}-mitsuba-avg.exr"), "--size", str(w), str(h),
                   "--spp", str(a.spp), "--seeds", str(a.seeds), "--m", str(depth),
                   "--each", each]
            cmd += ["--env", env] if env else []
            out = run(cmd, log)
            # The wrapper's render 1 (the tool's seed 0) compiles the
            # kernels; the others are timed. LAST.exr, the wrapper's copy
            # of the last render, is a by-product here: the seeds' own
            # files are read.
            timed = re.findall(r"mitsuba render ([0-9]+): ([0-9.]+) s", out)
            mi_t += [float(t) for k, t in timed if int(k) > 1]
        ours = [read_rgb(p) for p in images]
        mitsuba = [read_rgb(f"{each}{seed}.exr") for seed in range(a.seeds)]
        mi_avg = read_rgb(os.path.join(a.out, f"{name}-mitsuba-avg.exr"))
        ours_var, mi_var = variance(ours), variance(mitsuba)
        t_ours, t_mi = statistics.median(ours_t), statistics.median(mi_t)
        ratio = (mi_var * t_mi) / (ours_var * t_ours)
        ours_mean, mi_mean = sum(ours) / len(ours), mi_avg
        mask = (median_3x3(luminance(ours_mean)) < 1) & (median_3x3(luminance(mi_mean)) < 1)
        masked = (variance(mitsuba, mask) * t_mi) / (variance(ours, mask) * t_ours)
        bias = luminance(ours_mean)[mask].mean() / luminance(mi_mean)[mask].mean()
        print(f"| {name} (m={depth}) | {t_ours:.2f} | {ours_var:.3e} | {t_mi:.2f} | {mi_var:.3e} "
              f"| {ratio:.2f} | {masked:.2f} | {bias:.4f} |", flush=True)
        if a.spikes is not None:
            found = {who: spikes(imgs, a.spp, a.spikes) for who, imgs in
                     (("ours", ours), ("Mitsuba", mitsuba))}
            for who, (count, pixels, share) in found.items():
                print(f"  {name}, {who}: {count} render pixels above {a.spikes:g}, in "
                      f"{int(pixels.sum())} pixels holding {100 * share:.1f} % of the variance",
                      flush=True)
            common = found["ours"][1] & found["Mitsuba"][1]
            print(f"  {name}: {int(common.sum())} of those pixels in both renderers", flush=True)


if __name__ == "__main__":
    main()
