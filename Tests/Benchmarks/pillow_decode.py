"""Pillow's PNG decoding (zlib + its C unfilter) of the check benchmark's files: the anchor run-all prints beside
PngReader's, timed like it (process CPU time per image, the cheapest of BATCHES batches of >= 250 ms), from bytes in
memory. Usage: pillow_decode.py DATASET_FOLDER VIEWS BATCHES. Prints "key TAB value" lines like the benchmark's --tsv."""
import io
import sys
import time

from PIL import Image

folder, views, batches = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
kinds = [("rgba", ".png"), ("depth", "_depth_0000.png"), ("normal", "_normal_0000.png"), ("mask", "_mask_0000.png")]
for key, suffix in kinds:
    files = [open(f"{folder}/train/r_{i}{suffix}", "rb").read() for i in range(views)]
    first = Image.open(io.BytesIO(files[0]))
    first.load()
    raw = len(first.tobytes())
    best = float("inf")
    for _ in range(batches):
        start, runs = time.process_time(), 0
        while True:
            for data in files:
                Image.open(io.BytesIO(data)).load()
            runs += len(files)
            used = time.process_time() - start
            if used >= 0.25:
                break
        best = min(best, used / runs)
    ms = best * 1000
    print(f"check.png.{key}.pillow.ms\t{ms!r}")
    print(f"check.png.{key}.pillow.mbs\t{raw / 1e3 / ms!r}")
