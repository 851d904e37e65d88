"""Well-known implementations timed on the evaluation benchmark's own data (EvaluationBenchmark --dump-eval): scikit-image's
structural_similarity (its default, and set up like 3DGS: Gaussian σ 1.5, population covariance) on the 800x800 RGB pair,
and SciPy's cKDTree (build + query both ways) for Chamfer / F-score of 1 M against 1 M points. Process CPU time, the
cheapest of BATCHES runs. Usage: evaluate_anchor.py DUMP_FOLDER BATCHES. Prints "key TAB value" lines like --tsv;
explanations go to stderr."""
import sys
import time

import numpy as np

folder, batches = sys.argv[1], int(sys.argv[2])


def cpu(run, repeats):
    best, value = float("inf"), None
    for _ in range(repeats):
        start = time.process_time()
        value = run()
        best = min(best, (time.process_time() - start) * 1000)
    return best, value


truth = np.fromfile(f"{folder}/ssim-truth-800x800x3.f32", dtype=np.float32).reshape(800, 800, 3).astype(np.float64)
render = np.fromfile(f"{folder}/ssim-render-800x800x3.f32", dtype=np.float32).reshape(800, 800, 3).astype(np.float64)
try:
    from skimage.metrics import structural_similarity
    import skimage

    ms, value = cpu(lambda: structural_similarity(render, truth, channel_axis=-1, data_range=1.0), max(2, batches))
    print(f"eval.anchor.skimage.default.ms\t{ms}")
    print(f"eval.anchor.skimage.default.value\t{value}")
    ms, value = cpu(lambda: structural_similarity(render, truth, channel_axis=-1, data_range=1.0, gaussian_weights=True, sigma=1.5,
                                                  use_sample_covariance=False), max(2, batches))
    print(f"eval.anchor.skimage.gaussian.ms\t{ms}")
    print(f"eval.anchor.skimage.gaussian.value\t{value}")
    print(f"scikit-image {skimage.__version__}: SSIM default and Gaussian", file=sys.stderr)
except ImportError:
    print("no scikit-image (apt-get install python3-skimage): no SSIM anchor", file=sys.stderr)

try:
    from scipy.spatial import cKDTree
    import scipy

    recon = np.fromfile(f"{folder}/chamfer-recon.f32", dtype=np.float32).reshape(-1, 3).astype(np.float64)
    gt = np.fromfile(f"{folder}/chamfer-truth.f32", dtype=np.float32).reshape(-1, 3).astype(np.float64)

    def chamfer():
        d_acc, _ = cKDTree(gt).query(recon, k=1)
        d_comp, _ = cKDTree(recon).query(gt, k=1)
        return (d_acc.mean() + d_comp.mean()) / 2

    ms, value = cpu(chamfer, max(1, batches // 2))
    print(f"eval.anchor.ckdtree.ms\t{ms}")
    print(f"eval.anchor.ckdtree.value\t{value}")
    print(f"SciPy {scipy.__version__}: cKDTree Chamfer, single thread (workers=1)", file=sys.stderr)
except ImportError:
    print("no SciPy (apt-get install python3-scipy): no Chamfer anchor", file=sys.stderr)
