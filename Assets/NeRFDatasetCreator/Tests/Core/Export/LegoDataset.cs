using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A Blender-format dataset on disk built from the real nerf_synthetic lego train poses: transforms_train.json
    /// is the fixture itself (100 frames, extensionless ./train/r_i); val and test reuse poses 0–9 and 10–19 under
    /// ./val/r_i and ./test/r_i (the fixture has no val/test file). Every image is a blank 800×800 RGBA PNG.
    /// </summary>
    sealed class LegoDataset : IDisposable
    {
        public const int Size = 800;
        public const int ValCount = 10;
        public const int TestCount = 10;

        public LegoDataset()
        {
            Root = Path.Combine(Path.GetTempPath(), "nerf-export-tests-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Root);
            var train = JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath));
            CameraAngleX = (double)train["camera_angle_x"];
            var trainFrames = (JArray)train["frames"];
            File.WriteAllText(Path.Combine(Root, "transforms_train.json"), train.ToString());
            WriteSplit("val", trainFrames, 0, ValCount);
            WriteSplit("test", trainFrames, ValCount, TestCount);

            var png = TestPng.Encode(Size, Size, 8, PngInfo.ColorTypeRgba);
            Poses = new Dictionary<string, double[][]>();
            foreach (var split in new[] { "train", "val", "test" })
            {
                var json = JObject.Parse(File.ReadAllText(Path.Combine(Root, "transforms_" + split + ".json")));
                foreach (var frame in (JArray)json["frames"])
                {
                    var relative = ((string)frame["file_path"]).Substring(2) + ".png";
                    var path = Path.Combine(Root, relative);
                    Directory.CreateDirectory(Path.GetDirectoryName(path));
                    File.WriteAllBytes(path, png);
                    Poses[relative] = frame["transform_matrix"].ToObject<double[][]>();
                }
            }
        }

        public string Root { get; }
        public double CameraAngleX { get; }

        /// <summary>Source c2w of every image, by root-relative path with extension (e.g. <c>train/r_0.png</c>).</summary>
        public Dictionary<string, double[][]> Poses { get; }

        void WriteSplit(string split, JArray source, int first, int count)
        {
            var frames = new JArray();
            for (var i = 0; i < count; i++)
            {
                var frame = (JObject)source[first + i].DeepClone();
                frame["file_path"] = "./" + split + "/r_" + i;
                frames.Add(frame);
            }
            var json = new JObject { ["camera_angle_x"] = CameraAngleX, ["frames"] = frames };
            File.WriteAllText(Path.Combine(Root, "transforms_" + split + ".json"), json.ToString());
        }

        public void Dispose()
        {
            if (Directory.Exists(Root)) Directory.Delete(Root, true);
        }
    }
}
