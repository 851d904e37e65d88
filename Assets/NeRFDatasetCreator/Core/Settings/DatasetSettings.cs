using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Everything a dataset run needs, shared by the editor window, presets and batch mode, and stored in config
    /// files by <see cref="DatasetSettingsJson"/>. The defaults mirror nerf_synthetic: 800×800, its field of view,
    /// distance 4, train 100 on the upper hemisphere (golden-ratio semi-sphere), val 100 seeded-random on the upper
    /// hemisphere, test 200 on a two-turn orbit.
    /// </summary>
    [Serializable]
    public sealed class DatasetSettings
    {
        /// <summary>The config-file schema this code writes; files with other versions are read with a warning.</summary>
        public const int CurrentSchemaVersion = 1;

        public const int MinSize = 8;
        public const int MaxSize = 8192;
        public const int MinSupersampling = 1;
        /// <summary>The one supersampling limit: the writer's (<see cref="RawFrame.MaxSupersampling"/>), so nothing the settings allow can fail there.</summary>
        public const int MaxSupersampling = RawFrame.MaxSupersampling;
        public const int MaxViews = FormationMath.MaxViews;

        /// <summary>Bounds of <see cref="NormalisedTargetRadius"/> (output units).</summary>
        public const double MinNormalisedTargetRadius = 0.001;
        public const double MaxNormalisedTargetRadius = 1000;

        /// <summary>The most points <c>points3d.ply</c> may hold.</summary>
        public const int MaxPointCloudPoints = SurfaceSampler.MaxCount;

        /// <summary>The largest side of the supersampled render (size × supersampling): desktop GPUs' usual texture limit.</summary>
        public const int MaxRenderSize = 16384;

        /// <summary>The resolutions the window offers as presets; any size from 8 to 8192 is allowed.</summary>
        public static readonly int[] SizePresets = { 400, 800, 1600 };

        /// <summary>The dataset's folder name, also the default output folder's last component.</summary>
        public string Name = "nerf_dataset";

        /// <summary>Where the dataset folder goes; empty for the default <c>&lt;project&gt;/NeRFDatasets/&lt;Name&gt;</c>.</summary>
        public string OutputFolder = "";

        /// <summary>The scene (path, e.g. <c>Assets/Scenes/Lego.unity</c>) batch mode opens; empty for the open scene.</summary>
        public string Scene = "";

        /// <summary>The target's hierarchy path or name in the scene (batch mode); the window uses the object it is given.</summary>
        public string Target = "";

        public CameraSettings Camera = new CameraSettings();

        /// <summary>Distance from the target's centre to every camera, in Unity units (used unless <see cref="AutoDistance"/>).</summary>
        public double Distance = 4;

        /// <summary>Pick the distance from the target's bounding sphere and the field of view (see <see cref="AutoDistanceRule"/>).</summary>
        public bool AutoDistance;

        /// <summary>How much room the bounding sphere gets in the view with an automatic distance (≥ 1).</summary>
        public double AutoDistanceMargin = AutoDistanceRule.DefaultMargin;

        public SplitSettings Train = new SplitSettings { Count = 100, Formation = new FormationSettings { Kind = FormationKind.SemiSphere } };
        public SplitSettings Val = new SplitSettings { Count = 100, Formation = new FormationSettings { Kind = FormationKind.Random } };
        public SplitSettings Test = new SplitSettings { Count = 200, Formation = new FormationSettings { Kind = FormationKind.Orbit } };

        public int Width = 800;
        public int Height = 800;

        /// <summary>Each output pixel is the mean of k×k rendered pixels (anti-aliasing), k from 1 to 4.</summary>
        public int Supersampling = 1;

        public BackgroundSettings Background = new BackgroundSettings();

        /// <summary>
        /// The background eval_protocol.json names (<see cref="EvalProtocol.SettingsKey"/>: white, black, random or
        /// dataset); null for the default — white for a transparent background, the dataset's own for a solid one.
        /// </summary>
        public string EvaluationBackground;

        /// <summary>Seeds every random choice (random formations); the same seed gives the same dataset.</summary>
        public long Seed;

        public OverwritePolicy Overwrite = OverwritePolicy.Never;

        /// <summary>The loaders the dataset must work in; validation checks the splits each needs.</summary>
        public TargetLoaders Loaders = TargetLoaders.All;

        /// <summary>
        /// How output poses relate to the Unity world: recentred on the target (default), also scaled to
        /// nerf_synthetic's camera radius 4, or scaled so the target's bounding sphere has
        /// <see cref="NormalisedTargetRadius"/> (see <see cref="SceneNormalisation"/>).
        /// </summary>
        public NormalisationMode Normalisation = NormalisationMode.Recentre;

        /// <summary>
        /// The target's bounding-sphere radius in output units with <see cref="NormalisationMode.FitTargetRadius"/>.
        /// Every loader's box holds for radii up to 1.3 (3DGS's random initial cloud is ±1.3, nerfstudio's box ±1.5);
        /// 1 leaves room for bounds that are loose.
        /// </summary>
        public double NormalisedTargetRadius = 1.0;

        /// <summary>Points sampled on the target's mesh surfaces into <c>points3d.ply</c> (3DGS's initial cloud); 0 writes no file.</summary>
        public int PointCloudPoints;

        /// <summary>
        /// An environment capture (a split samples an inside-out volume): <c>points3d.ply</c> keeps only the scene's
        /// surface within this many Unity units of the volume boxes' centre; 0 picks
        /// <see cref="TargetPointCloud.DefaultRadiusFactor"/> × the boxes' half-diagonal (<see cref="TargetPointCloud.Region"/>).
        /// Not used without a volume split (the target's own surface is sampled).
        /// </summary>
        public double PointCloudRadius;

        /// <summary>
        /// Before a capture of more than <see cref="PreflightCheck.MinViews"/> views, the Unity capture renders a small
        /// calibration capture (a handful of the plan's views at low resolution, into a temporary folder), checks it with
        /// <c>nerf-dataset check</c>'s checks and stops with their words if it fails. On by default.
        /// </summary>
        public bool Preflight = true;

        /// <summary>
        /// The geometry pack: a whole-dataset capture of a target with meshes writes its triangle mesh in the output frame,
        /// <c>geometry/target_mesh.ply</c> (<see cref="TargetMeshPly"/>), recorded under <c>geometry</c> in
        /// dataset_config.json. On by default; off, no meshes are collected for it and neither is written.
        /// </summary>
        public bool GeometryPack = true;

        /// <summary>
        /// With <see cref="GeometryPack"/> on, a dynamic capture writes the target's mesh at every time step
        /// (<c>geometry/target_mesh_t0000.ply</c> …, <see cref="GeometryPackSteps"/>) instead of the one at its start time:
        /// <c>"geometryPack": "everyStep"</c> in config files. A static capture has one pose and writes
        /// <c>target_mesh.ply</c> either way.
        /// </summary>
        public bool GeometryPackEveryStep;

        /// <summary>Dynamic capture: what drives time, its range and steps, and how cameras meet it (static by default).</summary>
        public TimeSettings Time = new TimeSettings();

        /// <summary>Instance and semantic id maps with labels.json (<see cref="LabelSettings"/>; off by default).</summary>
        public LabelSettings Labels = new LabelSettings();

        /// <summary>The lens the images are taken through (issue 27); none by default (a pinhole).</summary>
        public LensSettings Lens = new LensSettings();

        /// <summary>Per-view exposure and white balance of the colour images (off by default): <see cref="ExposureSettings"/>.</summary>
        public ExposureSettings Exposure = new ExposureSettings();

        /// <summary>Linear HDR colour beside the PNGs, <c>r_&lt;i&gt;_hdr.exr</c> (off by default): <see cref="HdrSettings"/>.</summary>
        public HdrSettings Hdr = new HdrSettings();

        /// <summary>Motion blur and rolling shutter: each view exposed over a shutter interval (off by default; <see cref="MotionBlurSettings"/>).</summary>
        public MotionBlurSettings MotionBlur = new MotionBlurSettings();

        /// <summary>Exact optical flow, scene flow, occlusion and tracks of a dynamic capture (off by default; <see cref="FlowSettings"/>).</summary>
        public FlowSettings Flow = new FlowSettings();

        /// <summary>Material passes: albedo, metallic, roughness, specular, emission (off by default; <see cref="MaterialPassSettings"/>).</summary>
        public MaterialPassSettings Materials = new MaterialPassSettings();

        /// <summary>The same views under more lighting conditions, with lights.json (off by default; <see cref="RelightingSettings"/>).</summary>
        public RelightingSettings Relighting = new RelightingSettings();

        /// <summary>Sparse-view split files a capture or plan writes, one per train view count (<c>splits/sparse_&lt;n&gt;.json</c>, <see cref="SparseSplitFiles"/>); none by default.</summary>
        public int[] SparseViews = new int[0];

        public SplitSettings Split(DatasetSplit split)
        {
            switch (split)
            {
                case DatasetSplit.Train: return Train;
                case DatasetSplit.Val: return Val;
                case DatasetSplit.Test: return Test;
                default: throw new ArgumentOutOfRangeException(nameof(split));
            }
        }

        /// <summary>A deep copy, so an edited copy never changes a preset or a running capture's settings.</summary>
        public DatasetSettings Clone()
        {
            var copy = (DatasetSettings)MemberwiseClone();
            copy.Camera = Camera?.Clone();
            copy.Train = Train?.Clone();
            copy.Val = Val?.Clone();
            copy.Test = Test?.Clone();
            copy.Background = Background?.Clone();
            copy.Time = Time?.Clone();
            copy.Labels = Labels?.Clone();
            copy.Lens = Lens?.Clone();
            copy.Exposure = Exposure?.Clone();
            copy.Hdr = Hdr?.Clone();
            copy.MotionBlur = MotionBlur?.Clone();
            copy.Flow = Flow?.Clone();
            copy.Materials = Materials?.Clone();
            copy.Relighting = Relighting?.Clone();
            copy.SparseViews = (int[])SparseViews?.Clone();
            return copy;
        }

        /// <summary>The pinhole intrinsics of the output images.</summary>
        public CameraIntrinsics Intrinsics() => CameraIntrinsics.FromVerticalFov(Camera.VerticalFovDegrees, Width, Height);
    }
}
