using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A Unity cubemap's faces as texCUBE reads them. Face order: Unity's CubemapFace, PositiveX = 0, NegativeX,
    /// PositiveY, NegativeY, PositiveZ, NegativeZ = 5 (docs.unity3d.com/2022.3/Documentation/ScriptReference/CubemapFace.html).
    /// Within a face, Direct3D's cube-map addressing (learn.microsoft.com, "Cubic environment mapping (Direct3D 9)"; the
    /// same table as OpenGL 4.6 §8.13, table 8.19, with t from the top row): for the major axis ma and
    /// +X: (sc, tc) = (−z, −y); −X: (z, −y); +Y: (x, z); −Y: (x, −z); +Z: (x, −y); −Z: (−x, −y);
    /// column = (sc/|ma| + 1)/2 · N from the left, row = (tc/|ma| + 1)/2 · N from the top. Unity's world is left-handed
    /// like Direct3D's, and Skybox/Cubemap calls texCUBE with the Unity-world direction itself.
    /// </summary>
    public static class UnityCubemap
    {
        public const int PositiveX = 0, NegativeX = 1, PositiveY = 2, NegativeY = 3, PositiveZ = 4, NegativeZ = 5;

        /// <summary>The face of a Unity-world direction and its (s, t) in [0, 1]: s from the left, t from the top.</summary>
        public static int Face(Vector3d d, out double s, out double t)
        {
            double ax = Math.Abs(d.X), ay = Math.Abs(d.Y), az = Math.Abs(d.Z);
            int face;
            double sc, tc, ma;
            if (ax >= ay && ax >= az)
            {
                face = d.X >= 0 ? PositiveX : NegativeX;
                ma = ax;
                sc = d.X >= 0 ? -d.Z : d.Z;
                tc = -d.Y;
            }
            else if (ay >= az)
            {
                face = d.Y >= 0 ? PositiveY : NegativeY;
                ma = ay;
                sc = d.X;
                tc = d.Y >= 0 ? d.Z : -d.Z;
            }
            else
            {
                face = d.Z >= 0 ? PositiveZ : NegativeZ;
                ma = az;
                sc = d.Z >= 0 ? d.X : -d.X;
                tc = -d.Y;
            }
            s = (sc / ma + 1) / 2;
            t = (tc / ma + 1) / 2;
            return face;
        }

        /// <summary>The Unity-world direction (not normalised) of (s, t) on <paramref name="face"/>: the inverse of <see cref="Face"/>.</summary>
        public static Vector3d Direction(int face, double s, double t)
        {
            double sc = 2 * s - 1, tc = 2 * t - 1;
            switch (face)
            {
                case PositiveX: return new Vector3d(1, -tc, -sc);
                case NegativeX: return new Vector3d(-1, -tc, sc);
                case PositiveY: return new Vector3d(sc, 1, tc);
                case NegativeY: return new Vector3d(sc, -1, -tc);
                case PositiveZ: return new Vector3d(sc, -tc, 1);
                case NegativeZ: return new Vector3d(-sc, -tc, -1);
                default: throw new ArgumentOutOfRangeException(nameof(face), face, "a cubemap has faces 0…5");
            }
        }

        /// <summary>Bilinear sample (clamped at the face's edges) of six N×N RGB faces (rows top first) in direction <paramref name="unity"/>.</summary>
        public static void Sample(float[][] faces, int size, Vector3d unity, double[] result)
        {
            if (faces == null || faces.Length != 6) throw new ArgumentException("A cubemap has six faces (+X, −X, +Y, −Y, +Z, −Z).", nameof(faces));
            var face = Face(unity, out var s, out var t);
            var pixels = faces[face];
            if (pixels == null || pixels.Length != size * size * 3) throw new ArgumentException("Each face needs 3 floats (R G B) per pixel of size × size.", nameof(faces));
            double x = s * size - 0.5, y = t * size - 0.5;
            int x0 = (int)Math.Floor(x), y0 = (int)Math.Floor(y);
            double fx = x - x0, fy = y - y0;
            int xa = Clamp(x0, size), xb = Clamp(x0 + 1, size), ya = Clamp(y0, size), yb = Clamp(y0 + 1, size);
            for (var c = 0; c < 3; c++)
            {
                double top = pixels[(ya * size + xa) * 3 + c] * (1 - fx) + pixels[(ya * size + xb) * 3 + c] * fx;
                double bottom = pixels[(yb * size + xa) * 3 + c] * (1 - fx) + pixels[(yb * size + xb) * 3 + c] * fx;
                result[c] = top * (1 - fy) + bottom * fy;
            }
        }

        static int Clamp(int v, int n) => v < 0 ? 0 : v >= n ? n - 1 : v;
    }
}
