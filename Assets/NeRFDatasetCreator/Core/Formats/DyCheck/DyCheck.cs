using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// DyCheck's iPhone layout (KAIR-BAIR/dycheck ddf77a4, dycheck/datasets/iphone.py; the Nerfies files it shares are
    /// <see cref="Nerfies"/>'s), as DyCheck's iPhoneParser and Shape of Motion's iPhoneDataset (vye16/shape-of-motion
    /// 697d462, flow3d/data/iphone_dataset.py) read it:
    /// <list type="bullet">
    /// <item><c>splits/train.json</c>, <c>splits/val.json</c>: <c>frame_names</c>, <c>time_ids</c>, <c>camera_ids</c>
    /// (datasets/nerfies.py:348–358). DyCheck requires a training split's distinct time ids and camera ids to be
    /// consecutive (base.py:71–75) and indexes frames by (time id, camera id) (nerfies.py:89–93).</item>
    /// <item><c>extra.json</c>: <c>factor</c>, <c>fps</c>, <c>bbox</c>, <c>lookat</c>, <c>up</c> (iphone.py:1003–1010);
    /// factor is the rgb/depth level read (<c>rgb/{factor}x</c>, <c>depth/{factor}x</c>, iphone.py:973–976).</item>
    /// <item><c>depth/&lt;k&gt;x/&lt;id&gt;.npy</c>: float32 (H, W, 1) projective depth — the camera-space z of the hit, in
    /// the camera JSON's world units, 0 for none: the processor writes <c>camera.project(…, return_depth=True)</c> with
    /// <c>use_projective_depth</c> asserted (iphone.py:253, 288; geometry/camera.py:236–239), and the parser multiplies by
    /// scene.json's scale and divides by the ray's cosine to get distance along the ray (iphone.py:977–981). Ours is z
    /// already, so each value is the depth PNG's step × its unit, exactly (to float32).</item>
    /// <item>Time ids index the train frames: Shape of Motion keeps only <c>time_ids</c> below the split's number of frames
    /// (iphone_dataset.py:98–103), so a split with a time id at or above its frame count is refused (<see cref="TimeIdsPastFrameCount"/>).</item>
    /// </list>
    /// </summary>
    public static class DyCheck
    {
        public const string FolderName = "dycheck";
        public const string SplitsFolder = "splits";
        public const string ExtraFileName = "extra.json";
        public const string DepthFolder = "depth";

        /// <summary>The level written and named in extra.json: the full size, where depth is exact.</summary>
        public const int Factor = 1;

        /// <summary>A split file: the views' ids, time ids and camera ids, in order.</summary>
        public static JObject SplitJson(IEnumerable<NerfiesView> views)
        {
            var list = views.ToList();
            return new JObject
            {
                ["frame_names"] = new JArray(list.Select(v => (object)v.Id).ToArray()),
                ["time_ids"] = new JArray(list.Select(v => (object)v.TimeId).ToArray()),
                ["camera_ids"] = new JArray(list.Select(v => (object)v.CameraId).ToArray()),
            };
        }

        /// <summary>
        /// The time ids of <paramref name="views"/> that Shape of Motion drops (at or above the split's frame count,
        /// iphone_dataset.py:98–102), as one problem naming the split, or null when none is.
        /// </summary>
        public static ValidationProblem TimeIdsPastFrameCount(string split, IReadOnlyList<NerfiesView> views)
        {
            var past = views.Where(v => v.TimeId >= views.Count).ToList();
            if (past.Count == 0) return null;
            return new ValidationProblem("splits/" + split + ".json", past.Count + " of " + views.Count + " frames",
                "have time ids at or above the split's " + views.Count + " frames (e.g. " + past[0].Id + ", time id " + past[0].TimeId.ToString(CultureInfo.InvariantCulture) +
                "), and Shape of Motion's iPhone reader drops those (iphone_dataset.py:98–102), leaving its frames and times out of step.",
                "Capture every camera of the split at every time step (multi-view), or one view per step (monocular train).");
        }

        /// <summary>Distinct values of <paramref name="ids"/> that do not run 0, 1, 2, … without a gap, or null when they do (DyCheck's base.py:71–75 check, from 0).</summary>
        public static string Gap(IEnumerable<int> ids)
        {
            var distinct = ids.Distinct().OrderBy(i => i).ToList();
            for (var i = 0; i < distinct.Count; i++)
                if (distinct[i] != i) return string.Join(", ", distinct.Take(8)) + (distinct.Count > 8 ? ", …" : "");
            return null;
        }

        /// <summary>The (H, W, 1) float32 projective depth of a depth PNG's steps: step × unit, 0 where the step is 0.</summary>
        public static float[] Depth(ushort[] steps, double unit)
        {
            var depth = new float[steps.Length];
            for (var i = 0; i < steps.Length; i++) depth[i] = (float)(steps[i] * unit);
            return depth;
        }
    }
}
