using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading.Tasks;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes a real dataset folder through the capture's own Core path — <see cref="DatasetRun"/>'s plan, transforms
    /// and dataset_config.json, <see cref="ViewPipeline"/>'s per-view stages (lens, blur/sharp, then
    /// <see cref="ViewFileWriter"/>: difference matting, mask, 16-bit depth, normals, ids, exposure, PNG),
    /// <c>points3d.ply</c> with its record — from readbacks ray-traced per sample through NeRF's own ray formula
    /// (<see cref="NerfRay"/>, written here from the formula, not from the check's cameras) from each view's written
    /// <c>transform_matrix</c> and <c>camera_angle_x</c>: exactly what a correct capture of <see cref="AnalyticScene"/>
    /// must give. The test suite's datasets and <c>nerf-dataset demo</c> (<see cref="DemoDataset"/>) both come from here;
    /// the options marked "a planted fault" exist for the check's tests only. With a lens, each sample is traced along its distorted
    /// pixel's ray (the written model's undistortion), or — <see cref="Options.ThroughWideRender"/> — the capture's own
    /// path is taken: a wide pinhole render (<see cref="LensCapture.WideRender"/>) resampled by <see cref="LensResampler"/>.
    /// </summary>
    public static class AnalyticDataset
    {
        public sealed class Options
        {
            public int Width = 96, Height = 72, Supersampling = 2;
            public int Train = 10, Val = 3, Test = 3;
            public bool Normalised { get; set; }

            /// <summary>More than 1: a multi-view dynamic capture with moving content.</summary>
            public int TimeSteps { get; set; }

            /// <summary>With <see cref="TimeSteps"/>: a monocular capture instead (one train view per step; set Train to the steps).</summary>
            public bool Monocular { get; set; }
            public int PointCloud = 2000;

            /// <summary>Depth and normals rendered at the output size (the capture's default, CaptureOptions.DepthAndNormalAtOutputSize), else at the supersampled size.</summary>
            public bool DataAtOutputSize = true;

            /// <summary>Motion blur (static captures): each colour image is the average of the sub-frames' renders, the sharp one beside it.</summary>
            public MotionBlurSettings MotionBlur { get; set; }

            /// <summary>A planted fault: the depth pass holds the distance along each pixel's ray instead of z.</summary>
            public bool DepthAlongRay { get; set; }

            /// <summary>Instance and semantic maps with labels.json (<see cref="LabelObjects"/>: renderers are objects, classes from tags).</summary>
            public bool Labels { get; set; }

            /// <summary>Every material pass (<see cref="AnalyticMaterials"/>): settings <c>materials</c> with all five passes, and the passes rendered.</summary>
            public bool Materials { get; set; }

            /// <summary>One shard of a sharded capture (default: the whole dataset).</summary>
            public ShardSpec Shard { get; set; }

            /// <summary>The dataset folder relative to the project (batch mode's -nerfOut), so that shards of one config land apart; null for NeRFDatasets/&lt;name&gt;.</summary>
            public string DatasetFolder { get; set; }

            /// <summary>A planted fault: the instance maps are the mean of each pixel's sample ids (a filtered downsample), not their majority. Without <see cref="ThroughWideRender"/> (it reads the rendered frame).</summary>
            public bool BlendIds { get; set; }

            /// <summary>The lens setting (none by default).</summary>
            public LensSettings Lens = new LensSettings();

            /// <summary>With a lens: render the wide pinhole and resample it (the capture's path) instead of tracing each distorted ray.</summary>
            public bool ThroughWideRender { get; set; }

            /// <summary>The camera's vertical field of view and distance (Unity units); 0 for the defaults (39.6°, 4 or 8 normalised).</summary>
            public double VerticalFovDegrees { get; set; }
            public double Distance { get; set; }

            /// <summary>The loaders the settings list (all by default).</summary>
            public TargetLoaders Loaders = TargetLoaders.All;

            /// <summary>Further settings (e.g. exposure), applied last.</summary>
            public Action<DatasetSettings> Configure { get; set; }

            /// <summary>The tests' plain layout, or the demo's textured one with a crate (<see cref="AnalyticLook"/>).</summary>
            public AnalyticLook Look = AnalyticLook.Test;

            /// <summary>Views rendered at once (1: in plan order). The files do not depend on it: each view's are its own.</summary>
            public int Threads = 1;

            /// <summary>The provenance's time written into dataset_config.json (fixed, so that the files are the same every run).</summary>
            public DateTime Written = new DateTime(2026, 11, 27, 10, 0, 0, DateTimeKind.Utc);

            /// <summary>The replace policy of the dataset folder (never by default: a test writes into a fresh folder).</summary>
            public OverwritePolicy Overwrite = OverwritePolicy.Never;

            /// <summary>The geometry pack's meshes (Unity world) at a normalised time (<see cref="AnalyticSceneMeshes.At(double)"/>); null: no pack.</summary>
            public Func<double, IReadOnlyList<SurfaceMesh>> MeshesAt { get; set; }

            /// <summary><c>"geometryPack": "everyStep"</c>.</summary>
            public bool GeometryPackEveryStep { get; set; }

            /// <summary>
            /// Relighting's environment maps by condition name (output world, <see cref="EnvironmentMap"/>); an environment
            /// condition without one is lit by <see cref="AnalyticSky"/>.
            /// </summary>
            public IReadOnlyDictionary<string, EnvironmentMap> Environments { get; set; }

            /// <summary>Called with the pipeline once every view is written (its statistics: <see cref="ViewFileWriter.Matting"/>).</summary>
            public Action<ViewPipeline> AfterViews { get; set; }

            /// <summary>
            /// Called per view with its scene and the ray through each OUTPUT pixel position (<see cref="Rays"/>: NeRF's
            /// pinhole, or the written lens's distorted pixel — never the wide render), so a test can trace what a file's
            /// pixel centre must show, independently of the capture's stages.
            /// </summary>
            public Action<PlannedView, AnalyticScene, RayOf> OutputRays { get; set; }
        }

        /// <summary>
        /// The layout's objects as the Unity layer would describe them: the target "Analytic" holds Ball (the opaque
        /// sphere, tag Sphere), Glass (tag Sphere) and Slab (tag Ground), in the order <see cref="AnalyticScene"/>'s ids
        /// follow; listed here in another order, since ids must not depend on it.
        /// </summary>
        public static SceneObjectInfo[] LabelObjects(AnalyticLook look = AnalyticLook.Test)
        {
            var target = new SceneNode("Analytic", 0);
            var objects = new List<SceneObjectInfo>
            {
                new SceneObjectInfo(new[] { target, new SceneNode("Slab", 2, "Ground", "Default") }, 1),
                new SceneObjectInfo(new[] { target, new SceneNode("Ball", 0, "Sphere", "Default") }, 1),
                new SceneObjectInfo(new[] { target, new SceneNode("Glass", 1, "Sphere", "TransparentFX") }, 1),
            };
            // The demo's crate is the fourth box-after-spheres id (AnalyticScene's order), with a class of its own.
            if (look == AnalyticLook.Demo) objects.Add(new SceneObjectInfo(new[] { target, new SceneNode("Crate", 3, "Crate", "Default") }, 1));
            return objects.ToArray();
        }

        public static readonly Vector3d Centre = new Vector3d(1, 2, 3);
        const double Radius = 1.2;

        /// <summary>Renders the dataset into <paramref name="project"/>/NeRFDatasets/<paramref name="name"/> and returns its folder.</summary>
        public static string Write(string project, string name, Options options)
        {
            var run = Prepare(project, name, options);
            return Render(run, options);
        }

        /// <summary>The settings <see cref="Write"/> renders with (before <see cref="Options.Configure"/>).</summary>
        static DatasetSettings SettingsOf(string name, Options options)
        {
            var settings = new DatasetSettings { Name = name, Width = options.Width, Height = options.Height, Supersampling = options.Supersampling, Distance = options.Normalised ? 8 : 4,
                Lens = options.Lens.Clone(), Loaders = options.Loaders, Overwrite = options.Overwrite };
            if (options.VerticalFovDegrees > 0) settings.Camera.VerticalFovDegrees = options.VerticalFovDegrees;
            if (options.Distance > 0) settings.Distance = options.Distance;
            if (options.Normalised) settings.Normalisation = NormalisationMode.NerfSyntheticScale; // s = 4 / 8
            foreach (var (split, count) in new[] { (settings.Train, options.Train), (settings.Val, options.Val), (settings.Test, options.Test) })
            {
                split.Count = count;
                split.Depth = ExtraOutput.Png;
                split.Normal = ExtraOutput.Png;
                split.Mask = true;
            }
            if (options.TimeSteps > 1)
            {
                settings.Time.Mode = options.Monocular ? TimeMode.Monocular : TimeMode.MultiView;
                settings.Time.Steps = options.TimeSteps;
                settings.Time.StartSeconds = 0;
                settings.Time.EndSeconds = 1;
            }
            if (options.Labels) settings.Labels = new LabelSettings { Enabled = true, Instances = InstanceRule.Renderer, ClassFrom = ClassSource.Tag };
            if (options.MotionBlur != null) settings.MotionBlur = options.MotionBlur.Clone();
            if (options.Materials) settings.Materials = new MaterialPassSettings { On = true, Specular = true, Emission = true };
            settings.GeometryPackEveryStep = options.GeometryPackEveryStep;
            options.Configure?.Invoke(settings);
            return settings;
        }

        /// <summary>
        /// The run <see cref="Write"/> makes, prepared (plan, output folder checked) but not begun: its
        /// <see cref="DatasetRun.Problems"/> say why the folder cannot be written (<c>nerf-dataset demo</c> prints them).
        /// </summary>
        public static DatasetRun Prepare(string project, string name, Options options) =>
            DatasetRun.Prepare(SettingsOf(name, options), new PlanTarget(Centre, Radius, options.TimeSteps > 1 ? 1 : 0), project, options.Shard, options.DatasetFolder);

        /// <summary>Renders and writes the prepared <paramref name="run"/> (<see cref="Prepare"/>) and returns its folder.</summary>
        public static string Render(DatasetRun run, Options options)
        {
            if (!run.IsValid) throw new InvalidParameterException(run.Problems);
            var settings = run.FullPlan.Settings;
            var session = run.Begin();
            var labels = options.Labels ? LabelTable.Build(settings.Labels, LabelObjects(options.Look)) : null;
            // The capture's own per-view stages (Core's ViewPipeline). Without ThroughWideRender a lens's distorted rays are
            // traced here, per pixel: an independent oracle of the lens stage, whose frames are then at the output frame.
            var pipeline = options.ThroughWideRender ? new ViewPipeline(run.Plan, session, ExrWriter.Encode, labels)
                : new ViewPipeline(new ViewFileWriter(run.Plan, session, ExrWriter.Encode) { Labels = labels }, null);
            var lens = settings.Lens.ToDistortion();
            var wide = pipeline.WideRender;
            var scenes = new Dictionary<double, AnalyticScene>();
            var lightings = new Dictionary<double, Dictionary<string, SurfaceShading>>();
            var environments = EnvironmentsOf(settings, options);
            foreach (var view in run.Plan.Views)
            {
                var time = view.Time?.Normalised ?? 0;
                if (scenes.ContainsKey(time)) continue;
                scenes[time] = AnalyticScene.Layout(run.Plan.Normalisation, Centre, time, options.Look);
                lightings[time] = AnalyticLighting.For(settings, scenes[time], environments);
            }
            void WriteView(PlannedView view)
            {
                var scene = scenes[view.Time?.Normalised ?? 0];
                RayOf RaysAt(Matrix4x4d c2w) => wide != null ? Pinhole(c2w, wide) : Rays(c2w, run.Plan.Intrinsics, lens);
                var rays = RaysAt(view.TransformMatrix);
                int w = wide != null ? wide.Width : run.Plan.Intrinsics.Width, h = wide != null ? wide.Height : run.Plan.Intrinsics.Height;
                var frame = Render(scene, rays, w, h, options, run.Plan.Normalisation.Scale, options.Supersampling);
                // Relighting: the same samples under each condition (the views' own keys, in order).
                var shadings = lightings[view.Time?.Normalised ?? 0];
                if (view.RelitKeys.Count > 0)
                {
                    frame.Relit = new Dictionary<string, RawFrame>(StringComparer.Ordinal);
                    foreach (var key in view.RelitKeys) frame.Relit[key] = RenderColour(scene, rays, w, h, options.Supersampling, shadings[key]);
                }
                var data = options.DataAtOutputSize && options.Supersampling > 1 ? Render(scene, rays, w, h, options, run.Plan.Normalisation.Scale, 1) : frame;
                var blurred = view.Motion != null ? Blurred(scene, view, frame, run.Plan, options, RaysAt, w, h) : null;
                pipeline.Write(view, frame, data, blurred);
                options.OutputRays?.Invoke(view, scene, Rays(view.TransformMatrix, run.Plan.Intrinsics, lens));
                if (options.BlendIds) WriteBlendedIds(session, view, frame);
            }
            // The views are independent (ViewPipeline is thread-safe, one view per thread), so their files are the same in any order.
            if (options.Threads > 1) Parallel.ForEach(run.Plan.Views, new ParallelOptions { MaxDegreeOfParallelism = options.Threads }, WriteView);
            else foreach (var view in run.Plan.Views) WriteView(view);
            options.AfterViews?.Invoke(pipeline);
            var cloud = options.PointCloud > 0 ? AnalyticScene.Layout(run.Plan.Normalisation, Centre, 0, options.Look).Surface(options.PointCloud) : null;
            var meshesAt = options.MeshesAt;
            var provenance = new Provenance(options.Written) { Materials = options.Materials ? AnalyticMaterials.Facts() : null };
            run.Finish(session, provenance, cloud, meshesAt?.Invoke(0), labels,
                meshesAt == null || run.Plan.Time == null ? (Func<int, IReadOnlyList<SurfaceMesh>>)null : k => meshesAt(run.Plan.Time.NormalisedOf(k)),
                environments: environments);
            return run.DatasetFolder;
        }

        /// <summary>Each environment condition's map: the options' own, else <see cref="AnalyticSky"/>.</summary>
        static Dictionary<string, EnvironmentMap> EnvironmentsOf(DatasetSettings settings, Options options)
        {
            var maps = new Dictionary<string, EnvironmentMap>(StringComparer.Ordinal);
            if (settings.Relighting == null || !settings.Relighting.Enabled) return maps;
            EnvironmentMap sky = null;
            foreach (var c in settings.Relighting.Conditions)
                if (c.Kind == LightingKind.Environment)
                    maps[c.Name] = options.Environments != null && options.Environments.TryGetValue(c.Name, out var given) ? given : sky ?? (sky = AnalyticSky.Map());
            return maps;
        }

        /// <summary>The sub-frame average of the colour renders at the schedule's poses (<see cref="ViewPipeline.SubFrameAverage"/>); mask, depth, normals and ids of the mid pose.</summary>
        static RawFrame Blurred(AnalyticScene scene, PlannedView view, RawFrame sharp, CapturePlan plan, Options options, Func<Matrix4x4d, RayOf> raysAt, int w, int h)
        {
            var blur = plan.Settings.MotionBlur;
            var accumulator = ViewPipeline.SubFrameAverage(sharp.Width, sharp.Height, blur.SubFrames, blur.Readout, false);
            foreach (var sub in SubFrameSchedule.For(view.Motion, blur.SubFrames))
            {
                var render = Render(scene, raysAt(plan.Normalisation.CameraToWorld(sub.Pose)), w, h, options, plan.Normalisation.Scale, options.Supersampling);
                accumulator.Add(sub.Index, render.ColorOverBlack, render.ColorOverWhite);
            }
            var blurred = new RawFrame(sharp.Width, sharp.Height, sharp.Supersampling)
            {
                ColorOverBlack = new ushort[sharp.ColorOverBlack.Length], ColorOverWhite = new ushort[sharp.ColorOverWhite.Length],
                Mask = sharp.Mask, MaskBytesPerPixel = 1, Depth = sharp.Depth, Normals = sharp.Normals, NormalsInUnityWorld = false,
                InstanceIds = sharp.InstanceIds,
            };
            accumulator.Finish(blurred.ColorOverBlack, blurred.ColorOverWhite);
            return blurred;
        }

        /// <summary>A ray through continuous pixel (i, j) (top-left origin) whose camera-frame z component is −1, so its parameter is z-depth.</summary>
        public delegate void RayOf(double i, double j, out Vector3d origin, out Vector3d direction);

        /// <summary>NeRF's pinhole ray (<see cref="NerfRay"/>) without a lens; with one, the distorted pixel's ray: (i, j) → normalised (x_d, y_d), y down → undistort.</summary>
        public static RayOf Rays(Matrix4x4d c2w, CameraIntrinsics intrinsics, LensDistortion lens)
        {
            var rows = c2w.ToRows();
            if (lens == null)
                return (double i, double j, out Vector3d o, out Vector3d d) =>
                {
                    NerfRay(rows, intrinsics.CameraAngleX, intrinsics.Width, intrinsics.Height, i, j, out o, out d);
                };
            return (double i, double j, out Vector3d o, out Vector3d d) =>
            {
                if (!lens.Undistort((i - intrinsics.Cx) / intrinsics.FlX, (j - intrinsics.Cy) / intrinsics.FlY, out var x, out var y))
                    throw new InvalidOperationException("The lens does not image pixel (" + i + ", " + j + "): choose a milder distortion.");
                o = new Vector3d(rows[0][3], rows[1][3], rows[2][3]);
                d = Camera(rows, x, -y, -1);
            };
        }

        /// <summary>
        /// NeRF's own ray (bmild/nerf run_nerf_helpers.get_rays), written from the formula: for pixel (i, j), column i and
        /// row j from the top, the camera-space direction is ((i − W/2)/f, −(j − H/2)/f, −1) rotated by the c2w matrix's
        /// 3×3 part, f = 0.5·W / tan(0.5·camera_angle_x); the origin is its translation.
        /// </summary>
        static void NerfRay(double[][] c2w, double cameraAngleX, int width, int height, double i, double j, out Vector3d origin, out Vector3d direction)
        {
            var focal = 0.5 * width / Math.Tan(0.5 * cameraAngleX);
            origin = new Vector3d(c2w[0][3], c2w[1][3], c2w[2][3]);
            direction = Camera(c2w, (i - width * 0.5) / focal, -(j - height * 0.5) / focal, -1);
        }

        /// <summary>The wide pinhole render's ray: focal F, principal point (Cx, Cy) of <paramref name="wide"/>.</summary>
        public static RayOf Pinhole(Matrix4x4d c2w, LensPinholeCover wide)
        {
            var rows = c2w.ToRows();
            return (double i, double j, out Vector3d o, out Vector3d d) =>
            {
                o = new Vector3d(rows[0][3], rows[1][3], rows[2][3]);
                d = Camera(rows, (i - wide.Cx) / wide.Focal, -(j - wide.Cy) / wide.Focal, -1);
            };
        }

        static Vector3d Camera(double[][] rows, double x, double y, double z) => new Vector3d(
            rows[0][0] * x + rows[0][1] * y + rows[0][2] * z, rows[1][0] * x + rows[1][1] * y + rows[1][2] * z, rows[2][0] * x + rows[2][1] * y + rows[2][2] * z);

        /// <summary>The readbacks of one view of <paramref name="width"/> × <paramref name="height"/> pixels at supersampling <paramref name="k"/>: colour over black and white (halves), mask, eye z-depth (metric) and output-world normals, rows bottom first.</summary>
        public static RawFrame Render(AnalyticScene scene, RayOf rays, int width, int height, Options options, double scale, int k)
        {
            int w = width * k, h = height * k;
            var frame = new RawFrame(w, h, k)
            {
                ColorOverBlack = new ushort[w * h * 4], ColorOverWhite = new ushort[w * h * 4], Mask = new byte[w * h], MaskBytesPerPixel = 1,
                Depth = new float[w * h], Normals = new float[w * h * 4], NormalsInUnityWorld = false,
                InstanceIds = options.Labels ? new ushort[w * h] : null,
            };
            if (options.Materials)
            {
                frame.MaterialAlbedo = new float[w * h * 4];
                frame.MaterialMetallic = new float[w * h];
                frame.MaterialRoughness = new float[w * h];
                frame.MaterialSpecular = new float[w * h * 4];
                frame.MaterialEmission = new float[w * h * 4];
                frame.MaterialSupported = new byte[w * h];
            }
            var light = new Vector3d(0.3, -0.5, 0.8).Normalized();
            // The colour arrays of each compositing depth, reused from sample to sample (no garbage per ray).
            var scratch = new double[2 * (CompositeDepth + 1)][];
            for (var n = 0; n < scratch.Length; n++) scratch[n] = new double[3];
            double[] black = scratch[0], white = scratch[1];
            for (var ys = 0; ys < h; ys++)
                for (var xs = 0; xs < w; xs++)
                {
                    // The sample's position in output pixels (continuous, top-left origin), and NeRF's ray through it.
                    double i = (xs + 0.5) / k, j = (ys + 0.5) / k;
                    rays(i, j, out var o, out var d);
                    var p = ((h - 1 - ys) * w + xs); // readbacks are bottom row first
                    for (var c = 0; c < 3; c++)
                    {
                        black[c] = 0;
                        white[c] = 1;
                    }
                    Composite(scene, o, d, 0, light, black, white, out var first, out var normal, CompositeDepth, scratch, null);
                    for (var c = 0; c < 3; c++)
                    {
                        frame.ColorOverBlack[p * 4 + c] = Half(black[c]);
                        frame.ColorOverWhite[p * 4 + c] = Half(white[c]);
                    }
                    if (double.IsInfinity(first)) continue;
                    frame.Mask[p] = 255;
                    if ((frame.InstanceIds != null || options.Materials) && scene.Trace(o, d, 0, out _, out _, out var surface, out _, out var id))
                    {
                        if (frame.InstanceIds != null) frame.InstanceIds[p] = (ushort)id;
                        // The material passes render the nearest surface's own parameters, unlit (AnalyticMaterials).
                        if (options.Materials) AnalyticMaterials.Sample(frame, p, id, surface);
                    }
                    // The ray's camera-space z component is −1, so its parameter is the z-depth (output units).
                    var depth = options.DepthAlongRay ? first * d.Length : first;
                    frame.Depth[p] = (float)(depth / scale);
                    frame.Normals[p * 4] = (float)normal.X;
                    frame.Normals[p * 4 + 1] = (float)normal.Y;
                    frame.Normals[p * 4 + 2] = (float)normal.Z;
                }
            return frame;
        }

        /// <summary>
        /// The outgoing colour of a surface point (output world) with unit normal and base colour (linear), into
        /// <paramref name="result"/>: a relighting condition (<see cref="AnalyticLighting"/>).
        /// </summary>
        public delegate void SurfaceShading(Vector3d point, Vector3d normal, double[] albedo, double[] result);

        /// <summary>
        /// The colour pair (over black and over white, halves that may exceed 1) of one view lit by <paramref name="shading"/>,
        /// sampled exactly as <see cref="Render(AnalyticScene, RayOf, int, int, Options, double, int)"/> samples the view: a relit frame
        /// (<see cref="RawFrame.Relit"/>) with the same geometry, so the same alpha.
        /// </summary>
        public static RawFrame RenderColour(AnalyticScene scene, RayOf rays, int width, int height, int k, SurfaceShading shading)
        {
            int w = width * k, h = height * k;
            var frame = new RawFrame(w, h, k) { ColorOverBlack = new ushort[w * h * 4], ColorOverWhite = new ushort[w * h * 4] };
            var light = new Vector3d(0.3, -0.5, 0.8).Normalized();
            var scratch = new double[2 * (CompositeDepth + 1) + 2][]; // + the diffuse colour and the shaded colour (Composite)
            for (var n = 0; n < scratch.Length; n++) scratch[n] = new double[3];
            double[] black = scratch[0], white = scratch[1];
            for (var ys = 0; ys < h; ys++)
                for (var xs = 0; xs < w; xs++)
                {
                    double i = (xs + 0.5) / k, j = (ys + 0.5) / k;
                    rays(i, j, out var o, out var d);
                    var p = (h - 1 - ys) * w + xs; // readbacks are bottom row first
                    for (var c = 0; c < 3; c++)
                    {
                        black[c] = 0;
                        white[c] = 1;
                    }
                    Composite(scene, o, d, 0, light, black, white, out _, out _, CompositeDepth, scratch, shading);
                    for (var c = 0; c < 3; c++)
                    {
                        frame.ColorOverBlack[p * 4 + c] = HalfFloat.FromFloat((float)black[c]);
                        frame.ColorOverWhite[p * 4 + c] = HalfFloat.FromFloat((float)white[c]);
                    }
                }
            return frame;
        }

        /// <summary>How many surfaces along a ray are blended at most (the glass sphere's two and what lies behind).</summary>
        const int CompositeDepth = 3;

        /// <summary>
        /// Blends the surfaces along the ray front to back over black and over white, as the GPU does (out = F + T·B):
        /// Lambert-shaded colour, glass at its alpha. Returns the first surface's t and normal (depth and normals are of it).
        /// </summary>
        static void Composite(AnalyticScene scene, Vector3d o, Vector3d d, double after, Vector3d light, double[] black, double[] white,
            out double first, out Vector3d firstNormal, int depthLeft, double[][] scratch, SurfaceShading shading)
        {
            first = double.PositiveInfinity;
            firstNormal = Vector3d.Zero;
            if (depthLeft == 0 || !scene.Trace(o, d, after, out var t, out var normal, out var colour, out var alpha, out var objectId)) return;
            first = t;
            firstNormal = normal;
            var shade = 0.35 + 0.65 * Math.Max(0, Vector3d.Dot(normal, light));
            // This depth's arrays for what lies behind (depth CompositeDepth uses scratch[0, 1] for the sample itself).
            double[] behindBlack = scratch[2 * (CompositeDepth - depthLeft + 1)], behindWhite = scratch[2 * (CompositeDepth - depthLeft + 1) + 1];
            for (var c = 0; c < 3; c++)
            {
                behindBlack[c] = 0;
                behindWhite[c] = 1;
            }
            if (alpha < 1) Composite(scene, o, d, t + 1e-9, light, behindBlack, behindWhite, out _, out _, depthLeft - 1, scratch, shading);
            // A relighting condition's shading (AnalyticLighting) replaces the demo's fixed light; the demo's own stays as it was.
            // It lights the diffuse colour, base × (1 − metallic) of the object's material (AnalyticMaterials), the colour the
            // material passes and the inverse-rendering exports state (TensoIR's albedo is that diffuse colour).
            var shaded = shading == null ? null : scratch[scratch.Length - 1];
            if (shading != null)
            {
                var diffuse = scratch[scratch.Length - 2];
                var keep = 1 - AnalyticMaterials.Metallic(objectId);
                for (var c = 0; c < 3; c++) diffuse[c] = colour[c] * keep;
                shading(o + d * t, normal, diffuse, shaded);
            }
            for (var c = 0; c < 3; c++)
            {
                var surface = shaded != null ? shaded[c] : colour[c] * shade;
                black[c] = alpha * surface + (1 - alpha) * behindBlack[c];
                white[c] = alpha * surface + (1 - alpha) * behindWhite[c];
            }
        }

        /// <summary>The planted blend: each instance pixel the rounded mean of its k×k sample ids (background 0 included), as a filtered downsample gives.</summary>
        static void WriteBlendedIds(DatasetWriteSession session, PlannedView view, RawFrame frame)
        {
            int k = frame.Supersampling, ow = frame.OutputWidth, oh = frame.OutputHeight;
            var ids = new ushort[ow * oh];
            for (var oy = 0; oy < oh; oy++)
                for (var ox = 0; ox < ow; ox++)
                {
                    var sum = 0;
                    var first = RowOrder.SourceBlockRow(oy, oh, k) * frame.Width + ox * k;
                    for (var dy = 0; dy < k; dy++)
                        for (var dx = 0; dx < k; dx++) sum += frame.InstanceIds[first + dy * frame.Width + dx];
                    ids[oy * ow + ox] = (ushort)Math.Round(sum / (double)(k * k));
                }
            System.IO.File.WriteAllBytes(session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.InstancePng)), PngWriter.EncodeGray16(ids, ow, oh));
        }

        /// <summary>The nearest half float to a value in [0, 1] (the colour renders' format).</summary>
        public static ushort Half(double value)
        {
            if (!(value > 0)) return 0;
            if (value >= 1) return 0x3C00;
            var exponent = (int)Math.Floor(Math.Log(value, 2));
            if (exponent < -14) return (ushort)Math.Round(value / Math.Pow(2, -24)); // subnormal
            var mantissa = (int)Math.Round((value / Math.Pow(2, exponent) - 1) * 1024);
            if (mantissa == 1024) { mantissa = 0; exponent++; }
            return (ushort)(((exponent + 15) << 10) | mantissa);
        }
    }
}
