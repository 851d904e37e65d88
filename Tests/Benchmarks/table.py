"""Prints run-all's figures (the .tsv files in the folder given) as one table, .NET beside Mono."""
import glob
import os
import sys

folder = sys.argv[1]


def load(runtime):
    figures = {}
    for path in glob.glob(os.path.join(folder, f"{runtime}-*.tsv")) + ([os.path.join(folder, runtime + ".tsv")] if runtime in ("pillow", "anchor") else []):
        if os.path.exists(path):
            for line in open(path):
                key, value = line.rstrip("\n").split("\t")
                figures[key] = float(value)
    return figures


net, mono, pillow, anchor = load("dotnet"), load("mono"), load("pillow"), load("anchor")


def cell(figures, key, fmt):
    return fmt.format(figures[key]) if key in figures else "—"


def row(label, key, fmt, unit=""):
    if key not in net and key not in mono:
        return  # a section run-all --sections left out
    print(f"| {label} | {cell(net, key, fmt)}{unit if key in net else ''} | {cell(mono, key, fmt)}{unit if key in mono else ''} |")


print("| figure | .NET | Mono |")
print("|---|---|---|")
row("post-processing, capture layout: all steps (ms CPU)", "post.all.ms", "{:.2f}")
row("of which colour + alpha by difference matting (ms CPU)", "post.colour.ms", "{:.2f}")
row("plain copy of the same bytes (ms CPU)", "post.copy.ms", "{:.2f}")
row("post-processing / copy", "post.ratio", "{:.2f}", "×")
for image, label in [("rgba", "RGBA render with grain"), ("rgba-clean", "RGBA render without grain"), ("mask", "mask (gray 8)"),
                     ("depth", "depth (gray 16)"), ("normal", "normals (RGB 8)")]:
    for encoder, name in [("huffman", "Huffman (default)"), ("lz77", "Lz77"), ("zlib6", "DeflateStream level 6, Sub (old default)"), ("zlib1", "DeflateStream level 1, Sub")]:
        k = f"png.{image}.{encoder}"
        if k + ".ms" not in net and k + ".ms" not in mono:
            continue
        size = net.get(k + ".kb", mono.get(k + ".kb"))
        # Mono's DeflateStream is its own zlib (always level 6): its files differ from .NET's zlib-ng.
        other = f" (Mono {mono[k + '.kb']:.1f} KB)" if k + ".kb" in mono and abs(mono[k + ".kb"] - size) >= 0.05 else ""
        print(f"| PNG {label}, {name}: {size:.1f} KB{other} (MB/s) | {cell(net, k + '.mbs', '{:.0f}')} | {cell(mono, k + '.mbs', '{:.0f}')} |")
    for level in (1, 6):
        k = f"png.{image}.pillow{level}"
        if k + ".ms" in pillow:
            print(f"| PNG {label}, Pillow (zlib level {level}): {pillow[k + '.kb']:.1f} KB (MB/s) | {pillow[k + '.mbs']:.0f} (CPython) | |")
    if f"png.{image}.lz77.mbs" in net and f"png.{image}.zlib6.mbs" in net:
        print(f"| PNG {label}: Lz77 speed / level 6 speed | {net[f'png.{image}.lz77.mbs'] / net[f'png.{image}.zlib6.mbs']:.1f}× | "
              + (f"{mono[f'png.{image}.lz77.mbs'] / mono[f'png.{image}.zlib6.mbs']:.1f}×" if f"png.{image}.lz77.mbs" in mono else "—") + " |")
    if f"png.{image}.huffman.mbs" in net and f"png.{image}.zlib6.mbs" in net:
        print(f"| PNG {label}: Huffman speed / level 6 speed | {net[f'png.{image}.huffman.mbs'] / net[f'png.{image}.zlib6.mbs']:.1f}× | "
              + (f"{mono[f'png.{image}.huffman.mbs'] / mono[f'png.{image}.zlib6.mbs']:.1f}×" if f"png.{image}.huffman.mbs" in mono else "—") + " |")
row("motion blur 800×800 k=2, 16 sub-frames, before: per-view accumulator (ms CPU per view)", "blur.perview.ms", "{:.0f}")
row("  before: MB allocated per view", "blur.perview.mb", "{:.1f}")
row("  the sub-frames' readback copies alone (ms CPU per view)", "blur.copies.ms", "{:.0f}")
row("  now: one sum per run, copies + sum on one thread (ms CPU per view)", "blur.reused.ms", "{:.0f}")
row("  now: the sum on its worker thread (ms CPU per view, both threads)", "blur.worker.ms", "{:.0f}")
row("  now: MB allocated per view (sum on the calling thread)", "blur.reused.mb", "{:.3f}")
row("id maps 800×800 (supersampling 2): instance map, majority rule (ms CPU)", "labels.instance.ms", "{:.2f}")
row("  semantic map, majority rule over classes (ms CPU)", "labels.semantic.ms", "{:.2f}")
row("  instance map, 16-bit PNG encoding (ms CPU)", "labels.png.ms", "{:.2f}")
row("check of 300 views 800×800 with depth, normals, masks (s CPU)", "check.cpu.s", "{:.1f}")
row("  the same (s wall clock)", "check.wall.s", "{:.1f}")
row("  of which reading + PNG decoding (s wall clock)", "check.decode.s", "{:.1f}")
row("  reading + decoding all its PNGs once, alone (s CPU)", "check.decode.cpu.s", "{:.1f}")
row("  ms CPU per view", "check.ms-per-view", "{:.0f}")
for kind, label in [("rgba", "RGBA"), ("depth", "depth (gray 16)"), ("normal", "normals (RGB 8)"), ("mask", "mask (gray 8)")]:
    k = f"check.png.{kind}"
    if k + ".mbs" in net or k + ".mbs" in mono:
        print(f"| PNG decode, check dataset {label} (MB/s) | {cell(net, k + '.mbs', '{:.0f}')} | {cell(mono, k + '.mbs', '{:.0f}')} |")
    if k + ".pillow.mbs" in pillow:
        print(f"| PNG decode, check dataset {label}, Pillow (MB/s) | {pillow[k + '.pillow.mbs']:.0f} (CPython) | |")
        if k + ".mbs" in net:
            print(f"| PNG decode {label}: PngReader / Pillow speed | {net[k + '.mbs'] / pillow[k + '.pillow.mbs']:.2f}× | "
                  + (f"{mono[k + '.mbs'] / pillow[k + '.pillow.mbs']:.2f}×" if k + ".mbs" in mono else "—") + " |")
row("whole view, 1 thread (ms CPU per view)", "view.1.ms", "{:.1f}")
row("whole view, 1 thread (views/s per core)", "view.1.vps", "{:.1f}")
row("PNG encoding's share of the whole view", "view.png-share", "{:.0%}")
row(f"whole view, {int(net.get('view.n.workers', 0))} threads (views/s, wall clock)", "view.n.vps", "{:.1f}")
row("plan 300 000 views (ms)", "plan.build.ms", "{:.0f}")
row("plan 300 000 views (ms CPU)", "plan.build.cpu.ms", "{:.0f}")
row("stream their JSON files + commit (ms)", "plan.write.ms", "{:.0f}")
row("stream their JSON files + commit (ms CPU)", "plan.write.cpu.ms", "{:.0f}")
row("plan + JSON (ms wall)", "plan.total.ms", "{:.0f}")
row("plan + JSON (ms CPU of the process)", "plan.cpu.ms", "{:.0f}")
row("peak working set of that process (MB)", "plan.peak.mb", "{:.0f}")
row("COLMAP tracks, 100 000 points × 300 views of 800×800: decoding depth + mask (ms)", "tracks.decode.ms", "{:.0f}")
row("of which per view (ms)", "tracks.decode.view.ms", "{:.2f}")
row("COLMAP tracks: projecting and testing the points (ms)", "tracks.project.ms", "{:.0f}")
row("of which per point and view (ns)", "tracks.project.ns", "{:.1f}")
row("COLMAP tracks: tracked points in the sparsest view (min track 2)", "tracks.view.min", "{:.0f}")
row("COLMAP tracks: tracked points in the median view", "tracks.view.median", "{:.0f}")
row("COLMAP tracks: sparsest view with --points 10000", "tracks.view.min.10000", "{:.0f}")
row("COLMAP tracks: sparsest view with --points 1000", "tracks.view.min.1000", "{:.0f}")
row("COLMAP tracks: writing images + points3D, binary (ms)", "tracks.write.bin.ms", "{:.0f}")
row("COLMAP tracks: writing images + points3D, text (ms)", "tracks.write.text.ms", "{:.0f}")
row("evaluate: 3DGS SSIM of an 800×800 RGB pair (ms CPU)", "eval.ssim.ms", "{:.0f}")
row("evaluate: PSNR of the same pair (ms CPU)", "eval.psnr.ms", "{:.1f}")
if "eval.anchor.skimage.default.ms" in anchor:
    print(f"| scikit-image structural_similarity, default 7×7 uniform window (ms CPU; value {anchor['eval.anchor.skimage.default.value']:.6f}) | {anchor['eval.anchor.skimage.default.ms']:.0f} (NumPy) | |")
    print(f"| scikit-image, gaussian_weights σ 1.5, population covariance (ms CPU; value {anchor['eval.anchor.skimage.gaussian.value']:.6f}) | {anchor['eval.anchor.skimage.gaussian.ms']:.0f} (NumPy) | |")
if "eval.ssim.value" in net:
    print(f"| our SSIM value (3DGS formula) | {net['eval.ssim.value']:.6f} | {cell(mono, 'eval.ssim.value', '{:.6f}')} |")
row("evaluate: Chamfer + F-score, 1 M vs 1 M points (ms CPU)", "eval.chamfer.ms", "{:.0f}")
if "eval.anchor.ckdtree.ms" in anchor:
    print(f"| SciPy cKDTree, build both trees + query both ways (ms CPU; Chamfer {anchor['eval.anchor.ckdtree.value']:.7f}) | {anchor['eval.anchor.ckdtree.ms']:.0f} (C++) | |")
if "eval.chamfer.value" in net:
    print(f"| our Chamfer value | {net['eval.chamfer.value']:.7f} | {cell(mono, 'eval.chamfer.value', '{:.7f}')} |")
row("evaluate: 200 views of 800×800, all cores (s wall)", "eval.views.wall.s", "{:.1f}")
row("evaluate: 200 views of 800×800 (ms CPU per view)", "eval.views.cpu.ms", "{:.0f}")
row("flow: BVH build of a 100k-triangle mesh at both steps (ms CPU)", "flow.build.ms", "{:.0f}")
row("flow: one 800×800 view, forward flow with occlusion (ms CPU)", "flow.view.ms", "{:.0f}")
row("flow: per cast, primary and occlusion (ns CPU)", "flow.cast.ns", "{:.0f}")
row("flow: 300 views (s CPU, one thread)", "flow.300.s", "{:.0f}")
row("flow: the view's 640 000 primary rays alone (ms CPU)", "flow.primary.ms", "{:.0f}")
row("flow: per primary ray (ns CPU)", "flow.primary.ns", "{:.0f}")
row("flow: one view's flow on 1 thread (ms CPU)", "flow.view.cpu1.ms", "{:.0f}")
row("flow: one view's flow on 2 threads (ms CPU, both threads)", "flow.view.cpu2.ms", "{:.0f}")
row("flow: one view's flow on 1 thread (ms wall)", "flow.view.wall1.ms", "{:.0f}")
row("flow: one view's flow on 2 threads (ms wall)", "flow.view.wall2.ms", "{:.0f}")
row("flow: one pair's files, .flo + 2 PNG + EXR (ms CPU)", "flow.pair.write.ms", "{:.0f}")
row("flow: 300 views 800×800, 598 pairs, 1 thread (s, extrapolated)", "flow.video300.t1.s", "{:.0f}")
row("flow: 300 views 800×800, 598 pairs, 2 threads (s, extrapolated to 2 idle cores)", "flow.video300.t2.s", "{:.0f}")
if "flow.embree.primary.ms" in anchor:
    print(f"| Embree 3 (rtcIntersect1), one thread: BVH build (ms CPU) | {anchor['flow.embree.build.ms']:.0f} (C++) | |")
    print(f"| Embree: the view's 640 000 primary rays (ms CPU; {anchor['flow.embree.cast.ns']:.0f} ns a ray, {anchor['flow.embree.hits']:.0f} hits) | {anchor['flow.embree.primary.ms']:.0f} (C++) | |")
