using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>splits.json</c> beside an export whose format has no splits (LLFF, NeuS): the exported image names in order,
    /// the dataset file each came from, the indices of each split (nerf-pytorch's names <c>i_train</c>, <c>i_val</c>,
    /// <c>i_test</c>) and the background the images were composited over, so the dataset's protocol can still be followed.
    /// </summary>
    public static class SplitsRecord
    {
        public const string FileName = "splits.json";

        public static string Text(IReadOnlyList<ExportFrame> frames, IReadOnlyList<string> names, string background)
        {
            JArray Indices(string split) => new JArray(frames.Select((f, i) => (f, i)).Where(p => p.f.Split == split).Select(p => (object)p.i).ToArray());
            var json = new JObject
            {
                ["images"] = new JArray(names.Select(n => (object)n).ToArray()),
                ["source"] = new JArray(frames.Select(f => (object)f.ImagePath).ToArray()),
                ["i_train"] = Indices("train"),
                ["i_val"] = Indices("val"),
                ["i_test"] = Indices("test"),
                ["background"] = background,
            };
            return json.ToString(Formatting.Indented) + "\n";
        }
    }
}
