using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// nerf-pytorch's renders of the test split (<see cref="RenderLayout.NerfPytorch"/>; file and line in
    /// <see cref="RenderLayouts.Source"/>): during training every <c>--i_testset</c> iterations into
    /// <c>&lt;basedir&gt;/&lt;expname&gt;/testset_&lt;iter:06d&gt;/</c>, and with <c>--render_only --render_test</c> into
    /// <c>renderonly_test_&lt;iter:06d&gt;/</c>, as <c>000.png</c>, <c>001.png</c>, … over <c>poses[i_test]</c>: the test
    /// split's frames in file order, every <c>--testskip</c>-th one (its default is 8). So the n-th render is the n-th frame
    /// only when the renders were made with <c>--testskip 1</c>; any other count is refused, never paired by guess.
    /// </summary>
    static class NerfPytorchRenders
    {
        static readonly string[] Prefixes = { "testset_", "renderonly_test_" };

        /// <summary>True when <paramref name="root"/> is such a folder or holds one (the experiment folder).</summary>
        public static bool Holds(string root) => IterationOf(root) != null || Folders(root).Count > 0;

        public static RenderSet Read(string root, string split, IReadOnlyList<string> framePaths)
        {
            if (split != "test")
                throw RenderFolder.Problem(root, "holds nerf-pytorch renders, which are of the test split only (testset_<iter>/ and renderonly_test_<iter>/ render poses[i_test]).",
                    "Evaluate with --split test.");
            var notes = new List<string>();
            string folder;
            if (IterationOf(root) != null) folder = root;
            else
            {
                var folders = Folders(root);
                // The latest iteration; at one iteration the render-only pass (made from the saved weights on purpose) wins.
                folder = folders[folders.Count - 1].Folder;
                if (folders.Count > 1)
                    notes.Add("nerf-pytorch: " + folders.Count + " test renders (" + string.Join(", ", folders.Select(f => Path.GetFileName(f.Folder))) + "); evaluating the latest, " +
                              Path.GetFileName(folder) + ". Pass that folder itself to pick another.");
            }
            var numbered = new SortedDictionary<int, string>();
            var strangers = new List<string>();
            foreach (var name in Directory.GetFiles(folder).Select(Path.GetFileName).Where(n => !n.StartsWith(".", StringComparison.Ordinal)).OrderBy(n => n, StringComparer.Ordinal))
            {
                // '{:03d}.png': three digits, more from 1000 on; render_only also writes video.mp4 (line 670).
                var stem = name.EndsWith(".png", StringComparison.Ordinal) ? name.Substring(0, name.Length - 4) : null;
                if (stem != null && stem.Length >= 3 && (stem.Length == 3 || stem[0] != '0') &&
                    int.TryParse(stem, NumberStyles.None, CultureInfo.InvariantCulture, out var index)) numbered[index] = name;
                else if (name != "video.mp4") strangers.Add(name);
            }
            if (strangers.Count > 0)
                throw RenderFolder.Problem(folder, "holds " + RenderFolder.Describe(strangers) + ", which nerf-pytorch does not write there (it names renders 000.png, 001.png, … in the split's order).",
                    "Pass the testset_<iter> folder exactly as run_nerf.py wrote it.");
            var count = framePaths.Count;
            if (numbered.Count != count || (count > 0 && numbered.Keys.Last() != count - 1))
            {
                var skip = Enumerable.Range(2, 7).Reverse().FirstOrDefault(k => numbered.Count == (count + k - 1) / k);
                throw RenderFolder.Problem(folder, "holds " + numbered.Count + " renders but transforms_" + split + ".json lists " + count + " frames" +
                                                   (skip > 0 ? " — every " + skip + "th one, as nerf-pytorch's --testskip " + skip + " loads them (its default is 8)" : "") +
                                                   "; the n-th render is the n-th frame only when every frame was rendered.",
                    "Train or render with --testskip 1 (and without --half_res, whose renders are half the size), from this very dataset.");
            }
            var views = new List<RenderView>();
            for (var i = 0; i < count; i++) views.Add(new RenderView(i, framePaths[i], Path.Combine(folder, numbered[i])));
            return new RenderSet(RenderLayout.NerfPytorch, folder, views, notes);
        }

        /// <summary>The iteration of a <c>testset_&lt;iter&gt;</c> or <c>renderonly_test_&lt;iter&gt;</c> folder; null for any other.</summary>
        static int? IterationOf(string folder)
        {
            var name = Path.GetFileName(folder.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar));
            foreach (var prefix in Prefixes)
                if (name.StartsWith(prefix, StringComparison.Ordinal) &&
                    int.TryParse(name.Substring(prefix.Length), NumberStyles.None, CultureInfo.InvariantCulture, out var iteration)) return iteration;
            return null;
        }

        /// <summary>The render folders in an experiment folder, by iteration (a render-only pass after a testset of the same iteration).</summary>
        static List<(int Iteration, bool RenderOnly, string Folder)> Folders(string root)
        {
            var result = new List<(int, bool, string)>();
            if (!Directory.Exists(root)) return result;
            foreach (var folder in Directory.GetDirectories(root))
            {
                var iteration = IterationOf(folder);
                if (iteration != null && Directory.GetFiles(folder, "*.png").Length > 0)
                    result.Add((iteration.Value, Path.GetFileName(folder).StartsWith("renderonly_", StringComparison.Ordinal), folder));
            }
            result.Sort((a, b) => a.Item1 != b.Item1 ? a.Item1.CompareTo(b.Item1) : a.Item2.CompareTo(b.Item2));
            return result;
        }
    }
}
