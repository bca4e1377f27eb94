#!/usr/bin/env python3
"""The time per frame of a long render loop from Python, and whether it stays stable.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_render_loop.py [--frames 200] [--size 128] [--spp 16]

Renders the built-in vase under the paper's rig from the cameras of the paper's grid, one after
another in one process, as a data-generation loop does, and reports the median and the 95th
percentile time per frame, the first tenth against the last tenth (drift), and the process's
resident memory after the first ten frames and at the end (a leak grows it frame by frame). Sixteen
cameras are loaded first, outside the timing; the frames cycle through them, and each frame's time
is the call to matpredict.render alone.
"""
import argparse
import resource
import statistics
import time

import matpredict


def scene(cell, size, spp):
    return {
        "camera": {"grid": {"cell": cell, "radius": 0.6}, "width": size, "height": size},
        "lights": {"rig": {}},
        "objects": [{"builtin": "vase"}],
        "render": {"spp": spp, "seed": 0},
    }


def resident_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=200)
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()

    scenes = [matpredict.load_scene(scene([k, (7 * k) % 32], args.size, args.spp)) for k in range(16)]
    seconds = []
    memory_after_ten = None
    for k in range(args.frames):
        start = time.perf_counter()
        frame = matpredict.render(scenes[k % len(scenes)], threads=args.threads, aovs="default")
        seconds.append(time.perf_counter() - start)
        del frame
        if k == 9:
            memory_after_ten = resident_mib()
    tenth = max(1, args.frames // 10)
    ordered = sorted(seconds)
    print(f"{args.frames} frames of {args.size}x{args.size} at {args.spp} spp, default AOVs")
    print(f"per frame: median {statistics.median(seconds) * 1e3:.1f} ms, "
          f"95th percentile {ordered[int(0.95 * (len(ordered) - 1))] * 1e3:.1f} ms")
    print(f"first tenth {statistics.mean(seconds[:tenth]) * 1e3:.1f} ms, "
          f"last tenth {statistics.mean(seconds[-tenth:]) * 1e3:.1f} ms")
    print(f"peak resident memory after 10 frames {memory_after_ten:.0f} MiB, after {args.frames} {resident_mib():.0f} MiB")


if __name__ == "__main__":
    main()
