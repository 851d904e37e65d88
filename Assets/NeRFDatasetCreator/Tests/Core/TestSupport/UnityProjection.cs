using System;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Where a Unity camera puts a world point on screen, from Unity's documented conventions only: the camera
    /// looks along its local +Z; camera (view) space is OpenGL's, so view = (local.x, local.y, −local.z);
    /// <c>Camera.projectionMatrix</c> = <c>Matrix4x4.Perspective(fov, aspect, near, far)</c> (OpenGL clip space);
    /// <c>WorldToScreenPoint</c> maps NDC [−1, 1] to [0, W] × [0, H] with the origin at the bottom left.
    /// Independent of the Core conversion under test.
    /// </summary>
    static class UnityProjection
    {
        /// <summary>Continuous image coordinates (column u, row v from the TOP edge) of a Unity world point.</summary>
        public static bool TryProject(Vector3d cameraPosition, Quaterniond cameraRotation, double verticalFovDegrees,
            int width, int height, double near, double far, Vector3d worldPoint, out double u, out double v)
        {
            var inverse = new Quaterniond(-cameraRotation.X, -cameraRotation.Y, -cameraRotation.Z, cameraRotation.W);
            var local = inverse.Rotate(worldPoint - cameraPosition);
            double vx = local.X, vy = local.Y, vz = -local.Z;

            var cot = 1.0 / Math.Tan(verticalFovDegrees * Math.PI / 360.0);
            var aspect = (double)width / height;
            var clipX = cot / aspect * vx;
            var clipY = cot * vy;
            var clipZ = -(far + near) / (far - near) * vz - 2 * far * near / (far - near);
            var clipW = -vz;

            u = v = double.NaN;
            if (!(clipW > 0)) return false;
            var ndcX = clipX / clipW;
            var ndcY = clipY / clipW;
            var ndcZ = clipZ / clipW;
            if (Math.Abs(ndcX) > 1 || Math.Abs(ndcY) > 1 || Math.Abs(ndcZ) > 1) return false;
            u = (ndcX + 1) / 2 * width;
            var screenY = (ndcY + 1) / 2 * height;
            v = height - screenY;
            return true;
        }
    }
}
