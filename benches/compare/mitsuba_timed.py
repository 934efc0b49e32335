#!/usr/bin/env python3
"""Runs the Mitsuba 3 reference script with each of its renders timed.

    mitsuba_timed.py TOOL LAST.exr -- SCENE.dae OUT.exr --spp N --seeds N [--each PREFIX] ...

TOOL is `../shared/tools/mitsuba/dae_reference.py` (a maintainers' tool,
outside this repository); the arguments after `--` are its own. The tool
renders `--seeds` times and writes their average; this wrapper times every
`mi.render` call alone (kernel compilation happens in the first one, scene
loading outside all of them), prints `mitsuba render K: S s`, and writes the
last call's image, one seed at `--spp` samples, to LAST.exr. The calls
after the first measure rendering with compiled kernels, the fair
counterpart of this project's `render: S s` line, which excludes set-up.
"""
import os
import runpy
import sys
import time


def main():
    if len(sys.argv) < 4 or sys.argv[3] != "--":
        sys.exit("usage: mitsuba_timed.py TOOL LAST.exr -- SCENE.dae OUT.exr [tool options]")
    tool, last_path = sys.argv[1], sys.argv[2]
    sys.argv = [tool] + sys.argv[4:]
    import drjit as dr
    import mitsuba as mi

    calls = []
    variant_set = mi.set_variant

    def set_variant(*args, **kwargs):
        variant_set(*args, **kwargs)
        render = mi.render

        def timed(*a, **k):
            start = time.perf_counter()
            image = render(*a, **k)
            dr.eval(image)
            dr.sync_thread()
            seconds = time.perf_counter() - start
            calls.append(image)
            print(f"mitsuba render {len(calls)}: {seconds:.3f} s", flush=True)
            # Written here, after the clock stops: the tool may leave by
            # `os._exit` as soon as its own work is done.
            write(last_path, image, write_async=False)
            return image

        mi.render = timed
        write = mi.util.write_bitmap
        # Written at once (the default writes on a thread), so that every
        # file is whole when this process leaves.
        mi.util.write_bitmap = lambda *a, **k: write(*a, **{**k, "write_async": False})

    mi.set_variant = set_variant
    runpy.run_path(tool, run_name="__main__")
    sys.stdout.flush()
    # Dr.Jit's thread pool can hang the interpreter's shutdown once the
    # renders are done: leave at once, the files are written.
    os._exit(0)


if __name__ == "__main__":
    main()
