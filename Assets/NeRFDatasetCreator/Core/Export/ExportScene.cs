using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Everything an exporter writes: shared pinhole intrinsics, the frames of every split, and the optional extras
    /// (point cloud, applied normalisation). Paths are relative to <see cref="RootDirectory"/>.
    /// </summary>
    public sealed class ExportScene
    {
        public ExportScene(string rootDirectory, CameraIntrinsics intrinsics, IEnumerable<ExportFrame> frames,
            string pointCloudPath = null, SceneNormalisation normalisation = null, double depthUnitScale = DefaultDepthUnitScale,
            int? declaredAabbScale = null, double? targetReach = null, bool insideOut = false, LensDistortion lens = null, Newtonsoft.Json.Linq.JObject unityFrame = null)
        {
            RootDirectory = rootDirectory ?? throw new ArgumentNullException(nameof(rootDirectory));
            Intrinsics = intrinsics ?? throw new ArgumentNullException(nameof(intrinsics));
            Frames = (frames ?? throw new ArgumentNullException(nameof(frames))).ToList();
            PointCloudPath = string.IsNullOrEmpty(pointCloudPath) ? null : ExportPaths.Normalise(pointCloudPath);
            Normalisation = normalisation;
            if (!(depthUnitScale > 0) || double.IsInfinity(depthUnitScale))
                throw new InvalidParameterException(new[] { ValidationProblem.OutsideRange("depthUnitScale", depthUnitScale, 1e-9, 1e9) });
            DepthUnitScale = depthUnitScale;
            if (declaredAabbScale.HasValue && !AabbScale.IsValid(declaredAabbScale.Value))
                throw new ArgumentOutOfRangeException(nameof(declaredAabbScale), declaredAabbScale, "instant-ngp's aabb_scale is a power of two from 1 to 128.");
            if (targetReach.HasValue && !(targetReach.Value >= 0 && !double.IsInfinity(targetReach.Value)))
                throw new ArgumentOutOfRangeException(nameof(targetReach), targetReach, "a reach is a finite distance ≥ 0.");
            DeclaredAabbScale = declaredAabbScale;
            TargetReach = targetReach;
            InsideOut = insideOut;
            Lens = lens == null || lens.IsPinhole ? null : lens;
            UnityFrame = unityFrame;
        }

        /// <summary>
        /// dataset_config.json's <c>unity_frame</c> as recorded (<see cref="UnityFrameRecord"/>), or null: the JSON exports
        /// beside <c>scene_normalisation</c> carry it, so a converted dataset still knows its way back to Unity.
        /// </summary>
        public Newtonsoft.Json.Linq.JObject UnityFrame { get; }

        /// <summary>
        /// The lens distortion every image was taken through (<see cref="LensDistortion"/>, the same for all frames), or
        /// null for an ideal pinhole. Exporters carry it or refuse (Documentation~/exports.md, "Lens distortion").
        /// </summary>
        public LensDistortion Lens { get; }

        /// <summary>Whether the dataset records itself as an inside-out environment capture (<see cref="InsideOutRecord"/>).</summary>
        public bool InsideOut { get; }

        /// <summary>16-bit depth PNGs store round(z·1000): one step is a thousandth of an output unit (nerfstudio's default factor).</summary>
        public const double DefaultDepthUnitScale = BlenderTransformsWriter.DepthUnitScale;

        public string RootDirectory { get; }
        public CameraIntrinsics Intrinsics { get; }
        public IReadOnlyList<ExportFrame> Frames { get; }

        /// <summary>Relative path of a <c>points3d.ply</c> in the output frame, or null.</summary>
        public string PointCloudPath { get; }

        /// <summary>The recentring and scaling already applied to the poses (and to depth and points), or null if unknown.</summary>
        public SceneNormalisation Normalisation { get; }

        /// <summary>The <c>aabb_scale</c> the source's <c>transforms_train.json</c> declares (instant-ngp's cube), or null.</summary>
        public int? DeclaredAabbScale { get; }

        /// <summary>How far the target reaches from the output origin (output units), as the dataset records it; null when unknown.</summary>
        public double? TargetReach { get; }

        /// <summary>Output units per integer step of the depth PNGs.</summary>
        public double DepthUnitScale { get; }

        public bool HasDepth => Frames.Count > 0 && Frames.All(f => f.DepthPath != null);
        public bool HasMasks => Frames.Count > 0 && Frames.All(f => f.MaskPath != null);

        public IEnumerable<ExportFrame> Split(string split) => Frames.Where(f => f.Split == split);
    }
}
