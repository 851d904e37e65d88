using System;
using System.Collections.Generic;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's cameras as an instant-ngp camera path (<c>base_cam.json</c>, for the testbed's camera-path editor and
    /// scripts/run.py <c>--video_camera_path</c>). Format from src/camera_path.cu at abe236e: <c>CameraPath::save</c>
    /// (lines 123–133) writes loop, time, path, duration_seconds, spline_order; each keyframe (<c>to_json</c>, lines
    /// 88–98) holds R (a quaternion [x, y, z, w], tiny-cuda-nn vec_json.h), T, slice, scale, fov, aperture_size,
    /// timestamp. R and T are the testbed's own camera (<c>m_camera</c>), which <c>set_nerf_camera_matrix</c>
    /// (testbed.cu line 440) makes from a transforms matrix with <c>nerf_matrix_to_ngp</c> (nerf_loader.h lines
    /// 101–120): y and z columns negated, translation × scale + offset, then rows cycled (x, y, z) ← (y, z, x). Our
    /// instant-ngp export leaves scale and offset at their defaults 0.33 and 0.5 (nerf_loader.cu lines 163–164).
    /// <c>fov</c> is in degrees along the testbed's fov axis, vertical by default (testbed.h <c>m_fov_axis = 1</c>,
    /// testbed.cu line 4083). <c>spline_order</c> 0 makes every rendered frame one of the keyframes (camera_path.h
    /// line 185) rather than a spline between them. For a frame-by-frame comparison, run.py <c>--screenshot_transforms
    /// transforms_test.json</c> (lines 325–352) renders the split file's exact matrices.
    /// </summary>
    public static class NgpCameraPath
    {
        /// <summary>instant-ngp's default scene scale and offset (NERF_SCALE, nerf_loader.cu).</summary>
        public const double DefaultScale = 0.33;
        public const double DefaultOffset = 0.5;

        public static JObject Build(IReadOnlyList<Matrix4x4d> cameraToWorld, CameraIntrinsics intrinsics, double framesPerSecond = NerfstudioCameraPath.DefaultFramesPerSecond)
        {
            if (cameraToWorld == null || cameraToWorld.Count == 0) throw new ArgumentException("A camera path needs at least one camera.", nameof(cameraToWorld));
            if (intrinsics == null) throw new ArgumentNullException(nameof(intrinsics));
            InvalidParameterException.ThrowIfAny(ValidationProblem.OutsideRange("framesPerSecond", framesPerSecond, 0.001, 1000));
            var fov = intrinsics.CameraAngleY * 180 / Math.PI;
            var path = new JArray();
            for (var i = 0; i < cameraToWorld.Count; i++)
            {
                var m = ToNgp(cameraToWorld[i]);
                var q = Quaterniond.FromBasis(m.Column(0), m.Column(1), m.Column(2));
                var t = m.Translation;
                path.Add(new JObject
                {
                    ["R"] = new JArray(q.X, q.Y, q.Z, q.W),
                    ["T"] = new JArray(t.X, t.Y, t.Z),
                    ["slice"] = 0.0,
                    ["scale"] = 1.0,
                    ["fov"] = fov,
                    ["aperture_size"] = 0.0,
                    ["timestamp"] = i / framesPerSecond,
                });
            }
            return new JObject
            {
                ["loop"] = false,
                ["time"] = 0.0,
                ["path"] = path,
                ["duration_seconds"] = cameraToWorld.Count / framesPerSecond,
                ["spline_order"] = 0,
            };
        }

        /// <summary>instant-ngp's <c>nerf_matrix_to_ngp</c> with the default scale and offset.</summary>
        public static Matrix4x4d ToNgp(Matrix4x4d c2w)
        {
            var c0 = c2w.Column(0);
            var c1 = -c2w.Column(1);
            var c2 = -c2w.Column(2);
            var t = c2w.Translation * DefaultScale + new Vector3d(DefaultOffset, DefaultOffset, DefaultOffset);
            Vector3d Cycle(Vector3d v) => new Vector3d(v.Y, v.Z, v.X);
            return Matrix4x4d.FromColumns(Cycle(c0), Cycle(c1), Cycle(c2), Cycle(t));
        }
    }
}
