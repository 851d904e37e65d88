using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset demo</c>'s dataset: the demo look of the analytic scene (<see cref="AnalyticScene.Layout"/>,
    /// <see cref="AnalyticLook.Demo"/>: textured spheres, slab and crate) written by <see cref="AnalyticDataset"/> through
    /// the capture's own plan, <see cref="ViewPipeline"/> and <see cref="DatasetRun"/> — every pass, <c>points3d.ply</c>,
    /// the geometry pack — then checked by the real <see cref="DatasetCheck"/>, whose report goes into the dataset as
    /// <see cref="DatasetCheck.ReportFileName"/>, as after a capture in Unity. Same arguments, same bytes (the provenance
    /// time is fixed), except the report's timings. Design: Documentation~/maintainers/demo.md.
    /// </summary>
    public static class DemoDataset
    {
        /// <summary>The settings' <c>name</c> in dataset_config.json: how demo knows a folder is an earlier demo it may replace.</summary>
        public const string SettingsName = "nerf-dataset-demo";

        /// <summary>Train views (a nerf_synthetic-like count: 100 train, 10 val, 20 test) and image side in pixels.</summary>
        public const int DefaultViews = 100, DefaultSize = 200;

        public const int MinViews = 4, MaxViews = 2000, MinSize = 32, MaxSize = 2048;

        /// <summary>
        /// The blur preset's train views when <c>--views</c> is not given: each of its images is the average of
        /// <see cref="BlurSubFrames"/> renders besides the sharp one, so 100 views would take minutes, not seconds.
        /// </summary>
        public const int DefaultBlurViews = 40;

        const int BlurSubFrames = 4;

        /// <summary>
        /// The lens preset's smallest image side: its depth and mask are resampled from a wide render, and below this the
        /// pixels their resampled edges disagree on exceed the check's 0.5 % of a view's geometry.
        /// </summary>
        public const int MinLensSize = 128;

        /// <summary>The train views when <c>--views</c> is not given.</summary>
        public static int DefaultViewsFor(DemoPreset preset) =>
            preset == DemoPreset.Blur ? DefaultBlurViews : preset == DemoPreset.Relight ? DefaultRelightViews : DefaultViews;

        /// <summary>
        /// The relight preset's train views when <c>--views</c> is not given: each view is rendered again under each of its
        /// four conditions (the point light's with shadow rays), about 4.4× the plain demo's time per view.
        /// </summary>
        public const int DefaultRelightViews = 40;

        /// <summary>The createdUtc every demo records: fixed, so that the same command writes the same bytes.</summary>
        public static readonly DateTime Written = new DateTime(2000, 1, 1, 0, 0, 0, DateTimeKind.Utc);

        /// <summary>The dynamic preset's time steps (every camera at each).</summary>
        public const int TimeSteps = 5;

        /// <summary>The monocular preset's steps per second: under the TUM readers' 32, so that they keep every frame.</summary>
        public const double MonocularFrameRate = 30;

        /// <summary>The lens preset's field of view: wider than the default 39.6°, so that the distortion shows at the edges.</summary>
        const double LensVerticalFov = 55;

        /// <summary>
        /// The images' width and height for <c>--size</c>: square, but 4:3 for the dynamic preset (the width rounded down
        /// to a multiple of 4), the aspect 4DGaussians' N3DV reader resizes to (1352 × 1014), so that <c>--to dynerf</c> works.
        /// </summary>
        public static (int Width, int Height) Size(DemoPreset preset, int size)
        {
            if (preset != DemoPreset.Dynamic) return (size, size);
            var width = size - size % 4;
            return (width, width * 3 / 4);
        }

        /// <summary>The analytic dataset's options for a preset: <paramref name="views"/> train views, images of <see cref="Size"/>.</summary>
        public static AnalyticDataset.Options OptionsFor(DemoPreset preset, int views, int size)
        {
            // A dynamic capture films every time step from each camera: the views are spread over the steps.
            var perStep = preset == DemoPreset.Dynamic ? Math.Max(1, (views + TimeSteps - 1) / TimeSteps) : views;
            var (width, height) = Size(preset, size);
            var options = new AnalyticDataset.Options
            {
                Look = AnalyticLook.Demo,
                Width = width, Height = height, Supersampling = 2,
                Train = perStep, Val = Math.Max(1, perStep / 10), Test = Math.Max(1, perStep / 5),
                PointCloud = 5000,
                MeshesAt = t => AnalyticSceneMeshes.At(t, AnalyticLook.Demo),
                Threads = Math.Max(1, Environment.ProcessorCount),
            };
            switch (preset)
            {
                case DemoPreset.Dynamic:
                    options.TimeSteps = TimeSteps;
                    options.GeometryPackEveryStep = true;
                    break;
                case DemoPreset.Labels:
                    options.Labels = true;
                    break;
                case DemoPreset.Lens:
                    // The capture's own lens path: a wide pinhole render resampled into the distorted frame.
                    options.Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 };
                    options.ThroughWideRender = true;
                    options.DataAtOutputSize = false;
                    options.VerticalFovDegrees = LensVerticalFov;
                    break;
                case DemoPreset.Exposure:
                    options.Configure = s =>
                    {
                        s.Exposure.Mode = ExposureMode.Random;
                        s.Exposure.EvMin = -1;
                        s.Exposure.EvMax = 1;
                        s.Exposure.GainMin = 0.7;
                        s.Exposure.GainMax = 1.4;
                        s.Exposure.WriteClean = true;
                        s.Seed = 11;
                    };
                    break;
                case DemoPreset.Monocular:
                    // One train view per step, MonocularFrameRate steps a second: the SLAM readers keep every frame
                    // (TUM's keep only frames more than 1/32 s apart, TumRgbd.ReaderFrameRate).
                    options.TimeSteps = perStep;
                    options.Monocular = true;
                    options.Configure = s => s.Time.EndSeconds = (perStep - 1) / MonocularFrameRate;
                    break;
                case DemoPreset.Flow:
                    // The monocular preset's camera path, with the per-step meshes flow is computed from (by the capture) and
                    // tracks from about 10 query frames (DemoFlow), so --to shape-of-motion has what its reader needs.
                    options.TimeSteps = perStep;
                    options.Monocular = true;
                    options.GeometryPackEveryStep = true;
                    options.Configure = s =>
                    {
                        s.Time.EndSeconds = (perStep - 1) / MonocularFrameRate;
                        s.Flow = DemoFlow(perStep);
                    };
                    break;
                case DemoPreset.Hdr:
                    options.Configure = s => s.Hdr.On = true;
                    break;
                case DemoPreset.Materials:
                    options.Materials = true;
                    break;
                case DemoPreset.Relight:
                    options.Materials = true; // the inverse-rendering layouts' albedo, roughness and metallic
                    options.Configure = s =>
                    {
                        s.Relighting = RelightConditions();
                        s.Hdr.On = true; // the relit views' linear colour too (r_<i>_light_<key>_hdr.exr)
                    };
                    break;
                case DemoPreset.Blur:
                    options.MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.1, ShakeDegrees = 1, SubFrames = BlurSubFrames };
                    break;
            }
            return options;
        }

        /// <summary>
        /// The relight preset's conditions: the analytic sky (<see cref="AnalyticSky"/>, no project file: its source is named)
        /// at three rotations, and one shadow-casting point light above the target (output world, +Z up).
        /// </summary>
        public static RelightingSettings RelightConditions() => new RelightingSettings
        {
            On = true,
            Conditions = new List<LightingCondition>
            {
                new LightingCondition { Name = "sky", Kind = LightingKind.Environment, File = "analytic sky (AnalyticSky)", Rotations = new double[] { 0, 120, 240 } },
                new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new double[] { 2, -2, 3 }, Intensity = 25 },
            },
        };

        /// <summary>
        /// The flow demo's flow/: next-step flow both ways, and tracks from every k-th step (about 10 query frames,
        /// the fewest Shape of Motion's reader takes: ShapeOfMotion.MinFrames), so that --to shape-of-motion writes 10² track files.
        /// </summary>
        public static FlowSettings DemoFlow(int steps)
        {
            var every = Math.Max(1, steps / ShapeOfMotion.MinFrames);
            return new FlowSettings { On = true, TrackQueryFrames = Enumerable.Range(0, steps).Where(t => t % every == 0).Take(ShapeOfMotion.MinFrames).ToArray(), TrackStride = 8 };
        }

        /// <summary>
        /// Why demo must not write into <paramref name="folder"/>, or null: it writes only into a new or empty folder, or
        /// replaces an earlier demo (a dataset this plugin wrote whose settings are named <see cref="SettingsName"/>; the
        /// replace itself then proves every file in it is the plugin's, <see cref="OwnDataset"/>).
        /// </summary>
        public static ValidationProblem WhyNotWritable(string folder, out bool replacesEarlierDemo)
        {
            replacesEarlierDemo = false;
            var full = Path.GetFullPath(folder);
            if (File.Exists(full)) return new ValidationProblem("folder", full, "is an existing file, not a folder.", "Name a new folder, e.g. demo/lego.");
            if (!Directory.Exists(full) || !Directory.EnumerateFileSystemEntries(full).Any()) return null;
            var config = DatasetConfig.Read(full).Config;
            if (config != null && config.IsThisPlugin && (string)config.Settings?["name"] == SettingsName)
            {
                replacesEarlierDemo = true;
                return null;
            }
            return new ValidationProblem("folder", full,
                "already holds files that nerf-dataset demo did not write; demo writes only into a new or empty folder, or replaces an earlier demo.",
                "Name a new folder, e.g. demo/lego.");
        }

        /// <summary>Every reason not to write the demo into <paramref name="folder"/> (empty when it can).</summary>
        public static IReadOnlyList<ValidationProblem> Check(string folder, out OverwritePolicy policy)
        {
            policy = OverwritePolicy.Never;
            ValidationProblem why;
            bool replaces;
            try
            {
                why = WhyNotWritable(folder, out replaces);
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is IOException || e is UnauthorizedAccessException)
            {
                return new[] { new ValidationProblem("folder", folder ?? "", "cannot be used: " + e.Message, "Name another folder.") };
            }
            if (why != null) return new[] { why };
            policy = replaces ? OverwritePolicy.Replace : OverwritePolicy.Never;
            // The capture's own rules on top: not inside Unity's Assets, not inside another dataset, writable, a sane path.
            return SafeOutput.CheckOutputFolder(Path.GetFullPath(folder), null, policy, "folder");
        }

        /// <summary>
        /// Writes the demo dataset into <paramref name="folder"/> (checked first: <see cref="Check"/>; refused with
        /// <see cref="InvalidParameterException"/>), then checks it and writes the report into it.
        /// </summary>
        public static DemoResult Write(string folder, DemoPreset preset, int views = DefaultViews, int size = DefaultSize, Action<string> progress = null)
        {
            if (preset == DemoPreset.Lens && size < MinLensSize) throw new ArgumentOutOfRangeException(nameof(size), size, "the lens preset needs " + MinLensSize + " px or more");
            var problems = Check(folder, out var policy);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            var full = Path.GetFullPath(folder);
            var options = OptionsFor(preset, views, size);
            options.DatasetFolder = full;
            options.Overwrite = policy;
            // A fixed provenance time, so that the same command writes the same bytes (dataset_config.json's createdUtc).
            options.Written = Written;
            var run = AnalyticDataset.Prepare(null, SettingsName, options);
            if (!run.IsValid) throw new InvalidParameterException(run.Problems);
            var started = DateTime.UtcNow;
            progress?.Invoke("rendering " + run.Plan.Views.Count + " views of " + options.Width + " × " + options.Height + " px (" + DemoPresets.Name(preset) + ")");
            AnalyticDataset.Render(run, options);
            var rendered = (DateTime.UtcNow - started).TotalSeconds;
            progress?.Invoke("checking them (nerf-dataset check)");
            var report = DatasetCheck.Run(full, new DatasetCheckOptions());
            // As after a capture in Unity (PostCaptureCheck): the report goes into the dataset the run just wrote.
            File.WriteAllText(Path.Combine(full, DatasetCheck.ReportFileName), report.ToJson());
            return new DemoResult(full, preset, run.Plan.Views.Count, rendered, report);
        }
    }

    /// <summary>What <see cref="DemoDataset.Write"/> wrote.</summary>
    public sealed class DemoResult
    {
        public DemoResult(string folder, DemoPreset preset, int views, double renderSeconds, DatasetCheckReport check)
        {
            Folder = folder;
            Preset = preset;
            Views = views;
            RenderSeconds = renderSeconds;
            Check = check;
        }

        public string Folder { get; }
        public DemoPreset Preset { get; }
        public int Views { get; }
        public double RenderSeconds { get; }
        public DatasetCheckReport Check { get; }
    }
}
