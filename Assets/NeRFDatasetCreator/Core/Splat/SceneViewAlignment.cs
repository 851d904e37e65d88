using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The Scene view settings that put its camera exactly where a dataset camera was, with that camera's vertical field of
    /// view (the Editor's <i>View from camera i</i>, issue 34), and what the Scene view cannot reproduce.
    /// <para>
    /// The Scene view's camera sits at <c>pivot + rotation·(0, 0, −cameraDistance)</c> (UnityCsReference
    /// Editor/Mono/SceneView/SceneView.cs line 3123 at 2022.3.76f1, 3514 at 6000.0.78f1), with
    /// <c>cameraDistance = size / sin(fov/2)</c> in perspective (GetPerspectiveCameraDistance, lines 951-967 / 1063-1079;
    /// cameraDistance, 969-983 / 1081-1095), fov being <c>CameraSettings.fieldOfView</c> (853-857 / 964-968). That value
    /// is the vertical field of view when the view is wider than tall, else the horizontal one: the camera's vertical field
    /// is <c>2·atan(tan(fov/2) / aspect)</c> for aspect &lt; 1 (GetVerticalFOV, 3229-3239 / 3474-3483). Below 3° the
    /// view turns orthographic (kOrthoThresholdAngle, 344 / 421).
    /// </para>
    /// </summary>
    public sealed class SceneViewAlignment
    {
        /// <summary>The Scene view's field of view under which it would turn orthographic (kOrthoThresholdAngle).</summary>
        public const double OrthographicBelowDegrees = 3;

        SceneViewAlignment(Vector3d pivot, Quaterniond rotation, double size, double fieldOfView, double verticalFov, IReadOnlyList<string> inexact)
        {
            Pivot = pivot;
            Rotation = rotation;
            Size = size;
            FieldOfView = fieldOfView;
            VerticalFovDegrees = verticalFov;
            Inexact = inexact;
        }

        /// <summary><c>SceneView.pivot</c>: a point <c>pivotDistance</c> in front of the camera.</summary>
        public Vector3d Pivot { get; }

        /// <summary><c>SceneView.rotation</c>: the camera's rotation.</summary>
        public Quaterniond Rotation { get; }

        /// <summary><c>SceneView.size</c>: <c>pivotDistance·sin(fov/2)</c>, so that cameraDistance is <c>pivotDistance</c>.</summary>
        public double Size { get; }

        /// <summary><c>SceneView.cameraSettings.fieldOfView</c> in degrees.</summary>
        public double FieldOfView { get; }

        /// <summary>The dataset camera's vertical field of view, <c>2·atan(h / (2·fl_y))</c>, in degrees.</summary>
        public double VerticalFovDegrees { get; }

        /// <summary>What the Scene view shows differently from the dataset image, one sentence each (empty when nothing).</summary>
        public IReadOnlyList<string> Inexact { get; }

        /// <param name="pose">The camera in Unity's world (e.g. <see cref="ImportedCamera.Pose"/>).</param>
        /// <param name="intrinsics">Its pinhole: width, height, fl_x, fl_y, cx, cy in pixels.</param>
        /// <param name="sceneViewAspect">The Scene view camera's aspect, pixel width / height.</param>
        /// <param name="pivotDistance">How far in front of the camera the pivot goes (the distance to what is looked at).</param>
        public static SceneViewAlignment For(UnityPose pose, ImportedIntrinsics intrinsics, double sceneViewAspect, double pivotDistance)
        {
            if (intrinsics == null || !intrinsics.HasSize || !(intrinsics.FlX > 0) || !(intrinsics.FlY > 0))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("camera intrinsics", "missing", "are needed to match the dataset camera's field of view (w, h, fl_x, fl_y).",
                        "Use a dataset written by this plugin or a transforms file with w, h and fl_x/fl_y."),
                });
            if (!(sceneViewAspect > 0) || double.IsInfinity(sceneViewAspect)) throw new ArgumentOutOfRangeException(nameof(sceneViewAspect));
            if (!(pivotDistance > 0) || double.IsInfinity(pivotDistance)) throw new ArgumentOutOfRangeException(nameof(pivotDistance));

            double w = intrinsics.Width, h = intrinsics.Height;
            var halfTanV = h / (2 * intrinsics.FlY);
            var verticalFov = 2 * Math.Atan(halfTanV) * 180 / Math.PI;
            // GetVerticalFOV: for aspect < 1 the setting is the horizontal field, tan(F/2) = aspect·tan(v/2).
            var fov = sceneViewAspect < 1 ? 2 * Math.Atan(sceneViewAspect * halfTanV) * 180 / Math.PI : verticalFov;
            var size = pivotDistance * Math.Sin(fov * Math.PI / 360);
            var pivot = pose.Position + pose.Rotation.Forward * pivotDistance;

            var inexact = new List<string>();
            var dx = intrinsics.Cx - w / 2;
            var dy = intrinsics.Cy - h / 2;
            if (Math.Abs(dx) > 1e-6 || Math.Abs(dy) > 1e-6)
                inexact.Add("The principal point is off centre by (" + F(dx) + ", " + F(dy) + ") px; the Scene view's projection is always centred, so the view is shifted by that much.");
            if (Math.Abs(intrinsics.FlX - intrinsics.FlY) > 1e-9 * intrinsics.FlY)
                inexact.Add("fl_x (" + F(intrinsics.FlX) + ") differs from fl_y (" + F(intrinsics.FlY) + "); the Scene view has square pixels, so its horizontal field differs.");
            if (Math.Abs(sceneViewAspect - w / h) > 1e-3 * (w / h))
                inexact.Add("The Scene view is " + F(sceneViewAspect) + ":1, the image " + F(w / h) + ":1; the vertical field matches, so it shows more or less at the sides.");
            if (fov <= OrthographicBelowDegrees)
                inexact.Add("The field of view, " + F(fov) + "°, is below the Scene view's 3°, where it turns orthographic.");
            return new SceneViewAlignment(pivot, pose.Rotation, size, fov, verticalFov, inexact);
        }

        static string F(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);
    }
}
