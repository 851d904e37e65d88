using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The wireframe that stands for one camera in the preview, in Unity world coordinates: the pyramid from the
    /// camera's position to a rectangle <c>length</c> ahead whose proportions are the image's (so a wrong aspect or
    /// FOV shows), plus a small triangle on the rectangle's top edge, because a bare pyramid hides the camera's roll.
    /// </summary>
    public static class FrustumGeometry
    {
        /// <summary>Line segments per camera: 4 pyramid edges, 4 rectangle edges, 2 for the "up" triangle.</summary>
        public const int SegmentsPerCamera = 10;

        /// <summary>Points per camera in a segment list (two per segment, as Unity's <c>Handles.DrawLines</c> takes them).</summary>
        public const int PointsPerCamera = 2 * SegmentsPerCamera;

        /// <summary>
        /// The rectangle's corners, <paramref name="length"/> along the camera's forward: top-left, top-right,
        /// bottom-right, bottom-left as seen through the camera. Half-height = length·tan(vfov/2), half-width =
        /// half-height·aspect.
        /// </summary>
        public static Vector3d[] FarCorners(UnityPose pose, double verticalFovDegrees, double aspect, double length)
        {
            Check(verticalFovDegrees, aspect, length);
            var corners = new Vector3d[4];
            WriteCorners(pose, verticalFovDegrees, aspect, length, out corners[0], out corners[1], out corners[2], out corners[3]);
            return corners;
        }

        /// <summary>
        /// Writes the camera's <see cref="PointsPerCamera"/> segment end points into <paramref name="destination"/>
        /// from <paramref name="offset"/>: pairs (apex, corner) ×4, the rectangle's edges top, right, bottom, left,
        /// then the up triangle (top-edge quarter points to a tip half a half-height above the top edge's middle).
        /// </summary>
        public static void WriteSegments(UnityPose pose, double verticalFovDegrees, double aspect, double length,
            Vector3d[] destination, int offset)
        {
            Check(verticalFovDegrees, aspect, length);
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            if (offset < 0 || offset + PointsPerCamera > destination.Length)
                throw new ArgumentOutOfRangeException(nameof(offset), offset, "The destination has no room for " + PointsPerCamera + " points there.");

            WriteCorners(pose, verticalFovDegrees, aspect, length, out var tl, out var tr, out var br, out var bl);
            var apex = pose.Position;
            var i = offset;
            destination[i++] = apex; destination[i++] = tl;
            destination[i++] = apex; destination[i++] = tr;
            destination[i++] = apex; destination[i++] = br;
            destination[i++] = apex; destination[i++] = bl;
            destination[i++] = tl; destination[i++] = tr;
            destination[i++] = tr; destination[i++] = br;
            destination[i++] = br; destination[i++] = bl;
            destination[i++] = bl; destination[i++] = tl;

            var halfHeight = HalfHeight(verticalFovDegrees, length);
            var tip = (tl + tr) * 0.5 + pose.Rotation.Up * (0.5 * halfHeight);
            var left = tl * 0.75 + tr * 0.25;
            var right = tl * 0.25 + tr * 0.75;
            destination[i++] = left; destination[i++] = tip;
            destination[i++] = tip; destination[i] = right;
        }

        /// <summary>
        /// A frustum length that reads well at the rig's scale: an eighth of the rig distance, so neighbouring
        /// frusta of a 100-view sphere touch without piling up.
        /// </summary>
        public static double SuggestedLength(double rigDistance) => rigDistance > 0 && !double.IsInfinity(rigDistance) ? rigDistance / 8.0 : 1.0;

        static double HalfHeight(double verticalFovDegrees, double length) =>
            length * Math.Tan(verticalFovDegrees * Math.PI / 360.0);

        static void WriteCorners(UnityPose pose, double verticalFovDegrees, double aspect, double length,
            out Vector3d topLeft, out Vector3d topRight, out Vector3d bottomRight, out Vector3d bottomLeft)
        {
            var halfHeight = HalfHeight(verticalFovDegrees, length);
            var halfWidth = halfHeight * aspect;
            var rotation = pose.Rotation;
            var centre = pose.Position + rotation.Forward * length;
            var up = rotation.Up * halfHeight;
            var right = rotation.Right * halfWidth;
            topLeft = centre + up - right;
            topRight = centre + up + right;
            bottomRight = centre - up + right;
            bottomLeft = centre - up - right;
        }

        static void Check(double verticalFovDegrees, double aspect, double length)
        {
            ValidationProblem fov = null, aspectProblem = null, lengthProblem = null;
            if (!(verticalFovDegrees > 0 && verticalFovDegrees < 180))
                fov = new ValidationProblem("verticalFovDegrees", ValidationProblem.Format(verticalFovDegrees),
                    "must be more than 0 and less than 180 degrees.", "Use the camera's vertical field of view, e.g. 39.6.");
            if (!(aspect > 0) || double.IsInfinity(aspect))
                aspectProblem = new ValidationProblem("aspect", ValidationProblem.Format(aspect),
                    "must be a finite number above 0.", "Use the image width divided by its height.");
            if (!(length > 0) || double.IsInfinity(length))
                lengthProblem = new ValidationProblem("length", ValidationProblem.Format(length),
                    "must be a finite number above 0.", "Use a display length in Unity units, e.g. FrustumGeometry.SuggestedLength(distance).");
            InvalidParameterException.ThrowIfAny(fov, aspectProblem, lengthProblem);
        }
    }
}
