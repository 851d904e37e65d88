using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One frame pair's files as the flow check reads them (<see cref="FlowCheck"/>): the flow, the two masks and the
    /// scene flow, each checked for presence, format and size against the frame's image; what is wrong is a list of
    /// sentences naming the file, and the arrays are null then.
    /// </summary>
    public sealed class FlowPairFiles
    {
        public float[] Flow;
        public byte[] Occluded, Outside;

        /// <summary>(dx, dy, dz) per pixel, rows top first, and whether the pixel shows the target (A = 1); null when the record has no scene flow.</summary>
        public float[] SceneFlow;
        public bool[] OnTarget;

        public readonly List<string> Problems = new List<string>();

        public static FlowPairFiles Read(string root, FlowPair pair, bool sceneFlow, int width, int height)
        {
            var files = new FlowPairFiles();
            files.Flow = files.ReadFlow(root, pair.FlowFile, width, height);
            files.Occluded = files.ReadMask(root, pair.OccludedFile, width, height);
            files.Outside = files.ReadMask(root, pair.OutsideFile, width, height);
            if (sceneFlow) files.ReadSceneFlow(root, pair.SceneFlowFile, width, height);
            return files;
        }

        public bool Complete => Problems.Count == 0;

        string Path(string root, string relative, out bool exists)
        {
            var full = PathSafety.Inside(root, relative, out var outside);
            exists = full != null && File.Exists(full);
            if (full == null) Problems.Add(relative + ": its path " + outside + ".");
            else if (!exists) Problems.Add(relative + " is missing.");
            return full;
        }

        float[] ReadFlow(string root, string relative, int width, int height)
        {
            var full = Path(root, relative, out var exists);
            if (!exists) return null;
            try
            {
                var flow = FloFile.Read(full, out var w, out var h);
                if (w == width && h == height) return flow;
                Problems.Add(relative + " is " + w + " × " + h + " pixels, its frame's image " + width + " × " + height + ".");
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException) { Problems.Add(relative + " cannot be read: " + e.Message); }
            return null;
        }

        byte[] ReadMask(string root, string relative, int width, int height)
        {
            var full = Path(root, relative, out var exists);
            if (!exists) return null;
            try
            {
                var png = PngReader.Read(full);
                if (png.BitDepth != 8 || png.ColorType != PngInfo.ColorTypeGray) Problems.Add(relative + " is not an 8-bit grey PNG.");
                else if (png.Width != width || png.Height != height) Problems.Add(relative + " is " + png.Width + " × " + png.Height + " pixels, its frame's image " + width + " × " + height + ".");
                else return png.Samples;
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException) { Problems.Add(relative + " cannot be read: " + e.Message); }
            return null;
        }

        void ReadSceneFlow(string root, string relative, int width, int height)
        {
            var full = Path(root, relative, out var exists);
            if (!exists) return;
            try
            {
                var exr = ExrReader.Read(full);
                float[] r = exr.Channel("R"), g = exr.Channel("G"), b = exr.Channel("B"), a = exr.Channel("A");
                if (r == null || g == null || b == null || a == null) { Problems.Add(relative + " does not hold the channels R, G, B and A."); return; }
                if (exr.Width != width || exr.Height != height) { Problems.Add(relative + " is " + exr.Width + " × " + exr.Height + " pixels, its frame's image " + width + " × " + height + "."); return; }
                var n = width * height;
                SceneFlow = new float[3 * n];
                OnTarget = new bool[n];
                var notBinary = 0;
                for (var p = 0; p < n; p++)
                {
                    if (a[p] != 0 && a[p] != 1) notBinary++;
                    OnTarget[p] = a[p] == 1;
                    SceneFlow[3 * p] = r[p];
                    SceneFlow[3 * p + 1] = g[p];
                    SceneFlow[3 * p + 2] = b[p];
                }
                if (notBinary > 0) Problems.Add(relative + ": " + notBinary + " pixels have an A that is neither 0 (no target) nor 1 (on the target).");
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException) { Problems.Add(relative + " cannot be read: " + e.Message); }
        }
    }
}
