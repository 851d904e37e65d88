using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// <i>View from camera i</i>: puts a Scene view's camera exactly on a dataset camera (Unity world at capture) with that
    /// camera's vertical field of view, through the Scene view's public API only (UnityCsReference
    /// Editor/Mono/SceneView/SceneView.cs at 2022.3.76f1 / 6000.0.78f1):
    /// <list type="bullet">
    /// <item><c>in2DMode = false</c> first (502 / 591): in 2D mode <c>rotation</c> is fixed to identity (2902-2913 / 3124-3135).</item>
    /// <item><c>camera.aspect</c> (<c>camera</c>, 1050 / 1168) decides whether <c>cameraSettings.fieldOfView</c> is the vertical or
    /// the horizontal field (GetVerticalFOV, 3229-3239 / 3474-3483); <see cref="SceneViewAlignment"/> computes the value.</item>
    /// <item><c>cameraSettings.fieldOfView</c> (CameraSettings.fieldOfView, 853-857 / 964-968; <c>cameraSettings</c>, 887-891 / 998-1002),
    /// then <c>LookAt(point, direction, newSize, ortho: false, instant: true)</c> (3305-3329 / 3569-3593), which sets pivot,
    /// rotation and size at once and turns orthographic off. The camera then sits at pivot − forward·size/sin(fov/2)
    /// (3123 / 3514; 951-967 / 1063-1079): on the dataset camera.</item>
    /// </list>
    /// What it cannot do exactly — an off-centre principal point, fl_x ≠ fl_y, another aspect than the image, lens
    /// distortion — is returned as sentences (<see cref="SceneViewAlignment.Inexact"/>).
    /// </summary>
    public static class SceneViewCameraAlignment
    {
        /// <summary>Aligns <paramref name="view"/> to <paramref name="camera"/>, its pivot on <paramref name="lookAt"/>'s depth (or 1 unit ahead).</summary>
        public static SceneViewAlignment Align(SceneView view, ImportedCamera camera, Vector3? lookAt)
        {
            view.in2DMode = false;
            var position = camera.Pose.Position.ToVector3();
            var distance = lookAt.HasValue ? Vector3.Dot(lookAt.Value - position, camera.Pose.Rotation.Forward.ToVector3()) : 1f;
            if (!(distance > 1e-3f)) distance = 1f; // the target is behind or on the camera: any pivot ahead gives the same view
            var a = SceneViewAlignment.For(camera.Pose, camera.Intrinsics, view.camera.aspect, distance);
            view.cameraSettings.fieldOfView = (float)a.FieldOfView;
            view.LookAt(a.Pivot.ToVector3(), a.Rotation.ToQuaternion(), (float)a.Size, false, true);
            view.Repaint();
            return a;
        }

        /// <summary>The lines the window shows after aligning: the field of view set, then what differs.</summary>
        public static IReadOnlyList<string> Describe(int index, SceneViewAlignment a)
        {
            var lines = new List<string>
            {
                "Scene view on train camera " + index + ": vertical field of view " + a.VerticalFovDegrees.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture) + "°.",
            };
            lines.AddRange(a.Inexact);
            return lines;
        }
    }
}
