using System.Collections.Generic;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame key of the relighting sets (issue 38): <c>relit_paths</c>, an object from each condition's file key
    /// (<c>sunset_090</c>, <c>olat-03</c>) to that view's PNG under it (<c>./train/r_0_light_sunset_090.png</c>), and the
    /// lights file every dataset with relighting holds. The HDR EXR of a key, with <c>hdr</c> on, is the PNG's path with
    /// <c>_hdr.exr</c> for <c>.png</c> (as <c>r_0_hdr.exr</c> beside <c>r_0.png</c>).
    /// </summary>
    public static class RelightingKeys
    {
        public const string RelitPaths = "relit_paths";

        /// <summary>The lights record, relative to the dataset root.</summary>
        public const string LightsFile = "lights/lights.json";

        /// <summary>The folder of <see cref="LightsFile"/> and the environments' EXRs.</summary>
        public const string LightsFolder = "lights";

        /// <summary><c>"relit_paths": { "&lt;key&gt;": "./train/r_0_light_&lt;key&gt;.png", … }</c> when the view writes relit files.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v)
        {
            if (!v.Writes(DatasetFileKind.RelitPng) || v.RelitKeys.Count == 0) return;
            var paths = new string[v.RelitKeys.Count];
            for (var k = 0; k < paths.Length; k++) paths[k] = "./" + DatasetLayout.RelitRelativePath(v.Split, v.Index, v.RelitKeys[k], false);
            frame.StringObjectKey(RelitPaths, v.RelitKeys, paths);
        }

        /// <summary>The frame's <c>relit_paths</c> as written (<see cref="FrameRelit.None"/> without it).</summary>
        public static FrameRelit Read(JObject frame)
        {
            var token = frame?[RelitPaths];
            if (token == null) return FrameRelit.None;
            var relit = new FrameRelit();
            if (token.Type != JTokenType.Object)
            {
                relit.Problem = RelitPaths + " is " + token.Type.ToString().ToLowerInvariant() + ", not an object from each lighting key to its image.";
                return relit;
            }
            var paths = new List<KeyValuePair<string, string>>();
            foreach (var property in ((JObject)token).Properties())
            {
                if (property.Value.Type != JTokenType.String)
                {
                    relit.Problem = RelitPaths + "." + property.Name + " is not a path string.";
                    continue;
                }
                paths.Add(new KeyValuePair<string, string>(property.Name, (string)property.Value));
            }
            relit.Paths = paths;
            return relit;
        }

        /// <summary>The EXR beside a relit PNG: <c>r_0_light_sunset_090_hdr.exr</c> for <c>r_0_light_sunset_090.png</c>.</summary>
        public static string HdrPathOf(string pngPath) =>
            pngPath != null && pngPath.EndsWith(".png", System.StringComparison.Ordinal) ? pngPath.Substring(0, pngPath.Length - 4) + "_hdr.exr" : null;
    }
}
