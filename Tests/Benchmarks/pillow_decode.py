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
    # Bytes of samples as the PNG stores them (IHDR: width, height, bit depth, colour type), the measure PngReader's
    # figure uses; Pillow itself widens 16-bit grey to 32-bit "I" pixels.
    head = files[0]
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[head[25]]
    raw = width * height * channels * head[24] // 8
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
