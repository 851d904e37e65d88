using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with labels for the export tests: the analytic test dataset (real images, poses and transforms through
    /// the capture's writers), plus labels.json of <see cref="LabelHierarchy"/> under the "prefab" rule — ids 1 = City/Car
    /// (sibling 0), 2 = City/Tree, 3 = City/Car (sibling 2), 4 = City/Lamp; two objects share the name "Car" — and
    /// beside every image an instance map drawn by <see cref="IdAt"/>, so every expected pixel is known in closed form.
    /// </summary>
    static class LabelledTestDataset
    {
        public const int Width = 24, Height = 18;

        public static string Write(string project, string name = "labelled", bool labels = true)
        {
            var folder = AnalyticDataset.Write(project, name, new AnalyticDataset.Options { Width = Width, Height = Height, Supersampling = 1, Train = 3, Val = 1, Test = 2, PointCloud = 200 });
            if (!labels) return folder;
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag), LabelHierarchy.Renderers());
            File.WriteAllText(Path.Combine(folder, DatasetLayout.LabelsFileName), LabelsJson.Write(table));
            var frame = 0;
            foreach (var image in Images(folder))
            {
                var map = new ushort[Width * Height];
                for (var y = 0; y < Height; y++)
                    for (var x = 0; x < Width; x++)
                        map[y * Width + x] = (ushort)IdAt(frame, x, y);
                File.WriteAllBytes(Path.Combine(folder, LabelledDataset.InstanceMapOf(image)), PngWriter.EncodeGray16(map, Width, Height));
                frame++;
            }
            NameInstanceMaps(folder);
            return folder;
        }

        /// <summary>Adds each frame's instance_path, as the capture writes it: every reader takes a frame's files from its keys only.</summary>
        static void NameInstanceMaps(string folder)
        {
            foreach (var split in new[] { "train", "val", "test" })
            {
                var path = Path.Combine(folder, "transforms_" + split + ".json");
                var json = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(path));
                foreach (Newtonsoft.Json.Linq.JObject f in (Newtonsoft.Json.Linq.JArray)json["frames"])
                    f[LabelFrameKeys.Instance] = "./" + LabelledDataset.InstanceMapOf(ExportPaths.Normalise((string)f["file_path"]) + ".png");
                File.WriteAllText(path, json.ToString());
            }
        }

        /// <summary>The images in the loader's frame order (train, val, test; by index), relative to the dataset.</summary>
        public static List<string> Images(string folder)
        {
            var scene = BlenderDatasetLoader.Load(folder, new List<ValidationProblem>());
            var images = new List<string>();
            foreach (var f in scene.Frames) images.Add(f.ImagePath);
            return images;
        }

        /// <summary>
        /// The instance id at pixel (x, y) (row 0 at the top) of the <paramref name="frame"/>-th image: a background band on
        /// top, then the Car 1 on the left third, the Tree (even frames) or the Lamp (odd frames) in the middle third, and
        /// the Car 3 on the right third of frame 0 only.
        /// </summary>
        public static int IdAt(int frame, int x, int y)
        {
            if (y < Height / 4) return 0;
            if (x < Width / 3) return 1;
            if (x < 2 * Width / 3) return frame % 2 == 0 ? 2 : 4;
            return frame == 0 ? 3 : 0;
        }
    }
}
