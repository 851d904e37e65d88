using System.IO;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// A small rendered-looking dataset: the tool's own plan, then a blank 8-bit RGBA PNG of the planned size for every
    /// frame, and dataset_config.json removed so that nothing marks the folder as plan-only.
    /// </summary>
    static class RenderedDataset
    {
        public const int Width = 32;
        public const int Height = 24;
        public const int Train = 3;
        public const int Val = 2;
        public const int Test = 2;

        /// <summary>The plan alone (no images), as <c>nerf-dataset plan</c> leaves it.</summary>
        public static string PlanOnly(Scratch scratch, string name)
        {
            var folder = scratch.PathOf(name);
            var config = scratch.WriteText(name + ".json",
                "{ \"width\": " + Width + ", \"height\": " + Height + ", \"splits\": { \"train\": { \"count\": " + Train +
                " }, \"val\": { \"count\": " + Val + " }, \"test\": { \"count\": " + Test + " } } }");
            var run = ToolRun.Of("plan", "--config", config, "--out", folder);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            return folder;
        }

        public static string Create(Scratch scratch, string name)
        {
            var folder = PlanOnly(scratch, name);
            File.Delete(Path.Combine(folder, "dataset_config.json"));
            var png = TestPng.Encode(Width, Height, 8, PngInfo.ColorTypeRgba);
            foreach (var (split, count) in new[] { ("train", Train), ("val", Val), ("test", Test) })
            {
                Directory.CreateDirectory(Path.Combine(folder, split));
                for (var i = 0; i < count; i++) File.WriteAllBytes(Path.Combine(folder, split, "r_" + i + ".png"), png);
            }
            return folder;
        }
    }
}
