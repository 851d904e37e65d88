using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Unity's skybox conventions turned into the output world's (<see cref="Equirect"/>), from the built-in shaders
    /// Skybox/Panoramic (<c>Skybox-Panoramic.shader</c>) and Skybox/Cubemap (<c>Skybox-Cubed.shader</c>); sources with
    /// lines in Documentation~/maintainers/relighting.md.
    /// <para>
    /// Rotation: both shaders draw the sky's vertex v at RotateAroundYInDegrees(v, _Rotation) — (x, z) ← (cos·x − sin·z,
    /// sin·x + cos·z), y kept — and look the texture up with the unrotated v, so the texel of direction t is seen from
    /// R(t). In the output world (x, y, z) = (x, z, y) of Unity's that is (x, y) ← (cos·x − sin·y, sin·x + cos·y): Rz by
    /// the same angle, counter-clockwise about +Z seen from above. Unity's _Rotation of θ degrees is our rotation θ.
    /// </para>
    /// <para>
    /// Panoramic (latitude-longitude): ToRadialCoords gives u = 0.5 − atan2(z, x) / 2π and texture v = 1 − acos(y) / π
    /// (v from the bottom) for a Unity direction; with (x, z, y) → (x, y, z) that is our u and our v from the top, so an
    /// equirect texture is already in our convention. Cubemap: the face order is Unity's CubemapFace (+X, −X, +Y, −Y,
    /// +Z, −Z) and texCUBE addresses a face as Direct3D's cube-map table does (Unity's world is left-handed like D3D's).
    /// </para>
    /// </summary>
    public static class UnitySkybox
    {
        /// <summary>The rotation of lights.json for a skybox material's <c>_Rotation</c> (degrees about Unity's +Y): the same angle, in [0, 360).</summary>
        public static double ToOutputRotation(double unityRotationDegrees) => Normalised(unityRotationDegrees);

        /// <summary>The skybox <c>_Rotation</c> that shows an environment at our rotation <paramref name="outputDegrees"/>.</summary>
        public static double ToUnityRotation(double outputDegrees) => Normalised(outputDegrees);

        static double Normalised(double degrees)
        {
            var d = degrees % 360;
            return d < 0 ? d + 360 : d;
        }

        /// <summary>The shaders' RotateAroundYInDegrees(vertex, degrees), in Unity's world.</summary>
        public static Vector3d RotateAroundYInDegrees(Vector3d vertex, double degrees)
        {
            var alpha = degrees * Math.PI / 180;
            double s = Math.Sin(alpha), c = Math.Cos(alpha);
            // float2x2 m = (cos, −sin; sin, cos); mul(m, vertex.xz) → (x', z'); .xzy puts y back in the middle.
            return new Vector3d(c * vertex.X - s * vertex.Z, vertex.Y, s * vertex.X + c * vertex.Z);
        }

        /// <summary>Skybox/Panoramic's ToRadialCoords: (u, texture v from the bottom) of a Unity-world direction.</summary>
        public static void PanoramicUv(Vector3d unity, out double u, out double vFromBottom)
        {
            var n = unity.Normalized();
            var latitude = Math.Acos(Math.Max(-1, Math.Min(1, n.Y)));
            var longitude = Math.Atan2(n.Z, n.X);
            u = 0.5 - longitude / (2 * Math.PI);
            vFromBottom = 1 - latitude / Math.PI;
        }

        /// <summary>
        /// A latitude-longitude texture as Skybox/Panoramic shows it at _Rotation 0 (W×H RGB floats, rows top first as
        /// in the image file), resampled into the output-world equirect of <paramref name="width"/> × width/2 (bilinear,
        /// wrapping): an environment of lights.json.
        /// </summary>
        public static EnvironmentMap FromPanoramic(float[] rgb, int width, int height, int outputWidth)
        {
            if (rgb == null || width < 1 || height < 1 || rgb.Length != width * height * 3)
                throw new ArgumentException("The panorama needs 3 floats (R G B) per pixel of its width × height.", nameof(rgb));
            return Resample(outputWidth, (unity, result) =>
            {
                PanoramicUv(unity, out var u, out var v);
                Equirect.Sample(rgb, width, height, u, 1 - v, result);
            });
        }

        /// <summary>
        /// A cubemap as Skybox/Cubemap shows it at _Rotation 0 — six N×N RGB float faces in <see cref="UnityCubemap"/>'s
        /// order, rows top first as Direct3D addresses them — resampled into the output-world equirect of
        /// <paramref name="width"/> × width/2 (bilinear within a face).
        /// </summary>
        public static EnvironmentMap FromCubemap(float[][] faces, int size, int width) =>
            Resample(width, (unity, result) => UnityCubemap.Sample(faces, size, unity, result));

        static EnvironmentMap Resample(int width, Action<Vector3d, double[]> unitySample)
        {
            if (width < 2 || width % 2 != 0) throw new ArgumentOutOfRangeException(nameof(width), width, "an equirect map's width is even (W = 2H)");
            int height = width / 2;
            var rgb = new float[width * height * 3];
            var sample = new double[3];
            for (var row = 0; row < height; row++)
                for (var column = 0; column < width; column++)
                {
                    var d = Equirect.PixelDirection(column, row, width, height);
                    unitySample(BlenderConvention.ToUnity(d), sample);
                    var at = (row * width + column) * 3;
                    for (var c = 0; c < 3; c++) rgb[at + c] = (float)sample[c];
                }
            return new EnvironmentMap(width, height, rgb);
        }
    }
}
