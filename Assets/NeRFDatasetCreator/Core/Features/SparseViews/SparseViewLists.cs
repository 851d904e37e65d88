using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The sparse-view lists the papers use on nerf_synthetic, each from the code that defines it (sources in
    /// Documentation~/maintainers/train-and-evaluate.md, "Sparse-view splits"):
    /// <list type="bullet">
    /// <item>8 train views <c>[26, 86, 2, 55, 75, 93, 16, 73]</c>: DietNeRF's <c>run_nerf.py</c> re-seeds numpy with
    /// <c>--seed</c> (default 0, ajayjain/DietNeRF@ae5d7b4 dietnerf/run_nerf.py lines 580, 722) and draws
    /// <c>np.random.choice(i_train, size=args.max_train_views, replace=False)</c> (line 799) with <c>max_train_views = 8</c>
    /// (configs/dietnerf_8v/*.txt) over <c>i_train = 0 … 99</c>, the train split loaded first (load_blender.py). FreeNeRF's
    /// Blender experiments run the same code (Jiawei-Yang/FreeNeRF@c2d8bdc DietNeRF-pytorch/dietnerf/run_nerf.py lines
    /// 750, 785; configs/freenerf_8v). numpy's draw gives exactly this list (run by hand: np.random.seed(0);
    /// np.random.choice(np.arange(100), size=8, replace=False)).</item>
    /// <item>Test views: every 8th of transforms_test.json (0, 8, …, 192): <c>--testskip</c> defaults to 8 (DietNeRF
    /// run_nerf.py line 619; FreeNeRF's copy line 647) and load_blender.py keeps <c>meta['frames'][::testskip]</c> of val
    /// and test (lines 59–64).</item>
    /// </list>
    /// </summary>
    public static class SparseViewLists
    {
        /// <summary>DietNeRF / FreeNeRF's 8 nerf_synthetic train views (indices into transforms_train.json).</summary>
        public static readonly IReadOnlyList<int> DietNerfTrain8 = new[] { 26, 86, 2, 55, 75, 93, 16, 73 };

        /// <summary>DietNeRF / FreeNeRF's test stride: <c>--testskip 8</c>.</summary>
        public const int DietNerfTestSkip = 8;

        public const string DietNerfRule =
            "nerf_synthetic rig: the 8 train views DietNeRF and FreeNeRF train on (np.random.seed(0); np.random.choice(100 train views, 8, replace=False) in DietNeRF's run_nerf.py) " +
            "and every 8th test view (their --testskip 8: frames[::8] of transforms_test.json)";

        public const string DietNerfSource =
            "ajayjain/DietNeRF@ae5d7b4 dietnerf/run_nerf.py lines 580, 619, 722, 799 and dietnerf/load_blender.py lines 59-64; Jiawei-Yang/FreeNeRF@c2d8bdc DietNeRF-pytorch/dietnerf/run_nerf.py lines 647, 750, 785";

        /// <summary>Every <paramref name="skip"/>-th index of <paramref name="count"/>: <c>range(count)[::skip]</c>.</summary>
        public static IReadOnlyList<int> EveryNth(int count, int skip) => Enumerable.Range(0, count).Where(i => i % skip == 0).ToList();
    }
}
