"""Pillow's PNG encoder (zlib, levels 1 and 6) on the benchmark's raw images: the anchor run-all prints beside
the C# encoders, timed like them (process CPU time per run, the cheapest of BATCHES batches of >= 250 ms).
Usage: pillow_anchor.py RAW_FOLDER BATCHES. Prints "key TAB value" lines like the benchmark's --tsv."""
import array
import io
import sys
import time

from PIL import Image

folder, batches = sys.argv[1], int(sys.argv[2])
size = 800
images = [
    ("rgba", "rgba-800x800.raw", "RGBA", "RGBA", 4),
    ("rgba-clean", "rgba-clean-800x800.raw", "RGBA", "RGBA", 4),
    ("mask", "mask-800x800.raw", "L", "L", 1),
    ("depth", "depth16be-800x800.raw", "I;16", "I;16", 2),  # Pillow writes 16-bit PNGs from "I;16" (little-endian)
    ("normal", "normal-800x800.raw", "RGB", "RGB", 3),
]
for key, name, mode, raw_mode, bpp in images:
    data = open(f"{folder}/{name}", "rb").read()
    pixels = data
    if mode == "I;16":
        samples = array.array("H")
        samples.frombytes(data)
        samples.byteswap()
        pixels = samples.tobytes()
    image = Image.frombytes(mode, (size, size), pixels, "raw", raw_mode)
    for level in (1, 6):
        best, length = float("inf"), 0
        for _ in range(batches):
            start, runs = time.process_time(), 0
            while True:
                out = io.BytesIO()
                image.save(out, "PNG", compress_level=level)
                runs += 1
                used = time.process_time() - start
                if used >= 0.25:
                    break
            best = min(best, used / runs)
            length = out.tell()
        ms = best * 1000
        print(f"png.{key}.pillow{level}.ms\t{ms!r}")
        print(f"png.{key}.pillow{level}.kb\t{length / 1024!r}")
        print(f"png.{key}.pillow{level}.mbs\t{len(data) / 1e6 / best!r}")
