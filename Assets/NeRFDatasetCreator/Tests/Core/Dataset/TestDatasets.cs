using System.IO;
using System.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Builds datasets on disk for validator tests: the real lego transforms, or our own plan, with generated images.</summary>
    static class TestDatasets
    {
        static readonly System.Lazy<byte[]> LegoImage = new System.Lazy<byte[]>(() => TestPng.Encode(800, 800, 8, PngInfo.ColorTypeRgba));

        /// <summary>
        /// nerf_synthetic lego's transforms_train.json as the train split, and the same poses as val and test
        /// (file paths moved to ./val/ and ./test/), with an 800×800 8-bit RGBA PNG for every frame.
        /// </summary>
        public static void Lego(string folder)
        {
            Directory.CreateDirectory(folder);
            var train = File.ReadAllText(Fixtures.LegoTrainPath);
            var image = LegoImage.Value;
            foreach (var split in new[] { "train", "val", "test" })
            {
                File.WriteAllText(Path.Combine(folder, "transforms_" + split + ".json"), train.Replace("\"./train/", "\"./" + split + "/"));
                Directory.CreateDirectory(Path.Combine(folder, split));
                for (var i = 0; i < 100; i++)
                    File.WriteAllBytes(Path.Combine(folder, split, "r_" + i + ".png"), image);
            }
        }

        /// <summary>Writes the plan's JSON files through a write session and an image of the documented format for every planned PNG.</summary>
        public static void FromPlan(string folder, CapturePlan plan)
        {
            var session = DatasetWriteSession.Begin(folder, OverwritePolicy.Never);
            var w = plan.Intrinsics.Width;
            var h = plan.Intrinsics.Height;
            foreach (var file in plan.Views.SelectMany(v => v.Files))
            {
                var path = session.PathOf(file.RelativePath);
                switch (file.Kind)
                {
                    case DatasetFileKind.Color: TestPng.Write(path, w, h, 8, PngInfo.ColorTypeRgba); break;
                    case DatasetFileKind.DepthPng: TestPng.Write(path, w, h, 16, PngInfo.ColorTypeGray); break;
                    case DatasetFileKind.NormalPng: TestPng.Write(path, w, h, 8, PngInfo.ColorTypeRgb); break;
                    case DatasetFileKind.MaskPng: TestPng.Write(path, w, h, 8, PngInfo.ColorTypeGray); break;
                    default:
                        Directory.CreateDirectory(Path.GetDirectoryName(path));
                        File.WriteAllBytes(path, new byte[] { 0x76, 0x2f, 0x31, 0x01 }); // EXR magic; EXR content is not validated
                        break;
                }
            }
            DatasetMetadataFiles.Write(session, plan, new Provenance(new System.DateTime(2026, 1, 2, 3, 4, 5, System.DateTimeKind.Utc)));
            session.Commit();
        }
    }
}
