using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// lights.json's equirect convention on hand-derived directions, the rotation about +Z, Unity's skybox rotation and
    /// panorama/cubemap mapped onto them, and directions round-tripped through every trainer's convention
    /// (<see cref="LightConventions"/>, written from each loader's code).
    /// </summary>
    [TestFixture]
    public class EquirectConventionTests
    {
        const double Tolerance = 1e-9;

        /// <summary>Directions spread over the sphere (a fixed golden-spiral set, poles excluded), plus the axes.</summary>
        static IEnumerable<Vector3d> Directions()
        {
            foreach (var axis in new[] { Vector3d.UnitX, -Vector3d.UnitX, Vector3d.UnitY, -Vector3d.UnitY }) yield return axis;
            const int n = 200;
            for (var i = 0; i < n; i++)
            {
                var z = 1 - 2 * (i + 0.5) / n;
                var r = Math.Sqrt(1 - z * z);
                var phi = i * Math.PI * (3 - Math.Sqrt(5));
                yield return new Vector3d(r * Math.Cos(phi), r * Math.Sin(phi), z);
            }
        }

        static void Near(Vector3d a, Vector3d b, double tolerance, string what)
        {
            Assert.That((a - b).Length, Is.LessThan(tolerance), what + ": " + a + " vs " + b);
        }

        [Test]
        public void TheAxesFallWhereTheFormulaPutsThem()
        {
            // u = 0.5 − atan2(y, x)/2π, v = acos(z)/π: +X at the centre column, +Y a quarter to the left, −X at the seam, +Z at the top.
            foreach (var (d, u, v) in new[] { (Vector3d.UnitX, 0.5, 0.5), (Vector3d.UnitY, 0.25, 0.5), (-Vector3d.UnitY, 0.75, 0.5), (-Vector3d.UnitX, 0.0, 0.5) })
            {
                Equirect.Uv(d, out var gotU, out var gotV);
                Assert.That(gotU, Is.EqualTo(u).Within(Tolerance), d.ToString());
                Assert.That(gotV, Is.EqualTo(v).Within(Tolerance), d.ToString());
            }
            Equirect.Uv(Vector3d.UnitZ, out _, out var top);
            Assert.That(top, Is.EqualTo(0));
            Near(Equirect.Direction(0.5, 0), Vector3d.UnitZ, Tolerance, "the top row");
        }

        [Test]
        public void DirectionsRoundTripThroughUv()
        {
            foreach (var d in Directions())
            {
                Equirect.Uv(d, out var u, out var v);
                Assert.That(u, Is.GreaterThanOrEqualTo(0).And.LessThan(1));
                Near(Equirect.Direction(u, v), d, 1e-12, "round trip");
            }
        }

        [Test]
        public void ARotationIsCounterClockwiseAboutZSeenFromAbove()
        {
            Near(Equirect.RotateZ(Vector3d.UnitX, 90), Vector3d.UnitY, Tolerance, "+X by 90°");
            Near(Equirect.RotateZ(Vector3d.UnitY, 90), -Vector3d.UnitX, Tolerance, "+Y by 90°");
            // A map with one bright pixel: rotated by θ, its light arrives from Rz(θ)·d.
            var map = new EnvironmentMap(36, 18, new float[36 * 18 * 3]);
            int column = 9, row = 6;
            for (var c = 0; c < 3; c++) map.Rgb[(row * 36 + column) * 3 + c] = 1;
            var d = Equirect.PixelDirection(column, row, 36, 18);
            var sample = new double[3];
            map.Radiance(Equirect.RotateZ(d, 90), 90, sample);
            Assert.That(sample[0], Is.EqualTo(1).Within(1e-9));
            map.Radiance(d, 90, sample);
            Assert.That(sample[0], Is.EqualTo(0), "the light moved away from where it was");
            // 90° is 9 of 36 columns: the rotated map is the original rolled 9 columns to the left (u falls as atan2 grows).
            var rotated = map.Rotated(90);
            Assert.That(rotated.Rgb[(row * 36 + column - 9) * 3], Is.EqualTo(1).Within(1e-5));
        }

        [Test]
        public void BilinearSamplingWrapsAcrossTheSeam()
        {
            var rgb = new float[4 * 2 * 3];
            for (var row = 0; row < 2; row++)
            {
                rgb[(row * 4 + 0) * 3] = 2; // first column
                rgb[(row * 4 + 3) * 3] = 4; // last column
            }
            var sample = new double[3];
            Equirect.Sample(rgb, 4, 2, 0, 0.5, sample); // on the seam: half way between the first and last column's centres
            Assert.That(sample[0], Is.EqualTo(3).Within(1e-12));
        }

        [Test]
        public void UnitysSkyboxRotationIsOurRotation()
        {
            // Skybox-Panoramic/-Cubed: the texel of direction t is drawn at RotateAroundYInDegrees(t, _Rotation).
            foreach (var degrees in new[] { 0.0, 30, 90, 200, 359 })
                foreach (var t in Directions())
                {
                    var unity = BlenderConvention.ToUnity(t);
                    var drawnAt = BlenderConvention.FromUnity(UnitySkybox.RotateAroundYInDegrees(unity, degrees));
                    Near(drawnAt, Equirect.RotateZ(t, UnitySkybox.ToOutputRotation(degrees)), 1e-12, degrees + "°");
                }
            // Hand-derived: _Rotation 90 draws Unity's +X texel at (cos 90·1 − sin 90·0, ·, sin 90·1 + cos 90·0) = Unity +Z = our +Y.
            Near(UnitySkybox.RotateAroundYInDegrees(new Vector3d(1, 0, 0), 90), new Vector3d(0, 0, 1), Tolerance, "Unity +X by 90");
            Assert.That(UnitySkybox.ToOutputRotation(370), Is.EqualTo(10).Within(1e-12));
            Assert.That(UnitySkybox.ToOutputRotation(-90), Is.EqualTo(270));
            Assert.That(UnitySkybox.ToUnityRotation(UnitySkybox.ToOutputRotation(123)), Is.EqualTo(123));
        }

        [Test]
        public void AUnityPanoramaIsAlreadyInOurConvention()
        {
            // ToRadialCoords for Unity +Z (forward): u = 0.5 − atan2(1, 0)/2π = 0.25, v = 0.5; Unity +Z is our +Y, whose u is 0.25.
            UnitySkybox.PanoramicUv(new Vector3d(0, 0, 1), out var u, out var v);
            Assert.That((u, v), Is.EqualTo((0.25, 0.5)));
            UnitySkybox.PanoramicUv(new Vector3d(0, 1, 0), out _, out var up);
            Assert.That(up, Is.EqualTo(1), "Unity's +Y is the texture's top (v = 1 from the bottom)");
            int w = 32, h = 16;
            var rgb = new float[w * h * 3];
            for (var i = 0; i < rgb.Length; i++) rgb[i] = (i * 7919 % 1000) / 100f;
            var map = UnitySkybox.FromPanoramic(rgb, w, h, w);
            for (var i = 0; i < rgb.Length; i++) Assert.That(map.Rgb[i], Is.EqualTo(rgb[i]).Within(1e-4), "pixel " + i / 3);
        }

        [Test]
        public void CubemapFacesFollowUnitysOrderAndDirect3DsAddressing()
        {
            // Each face's centre looks along its axis, in CubemapFace order.
            var axes = new[] { new Vector3d(1, 0, 0), new Vector3d(-1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(0, -1, 0), new Vector3d(0, 0, 1), new Vector3d(0, 0, -1) };
            for (var f = 0; f < 6; f++)
            {
                Assert.That(UnityCubemap.Face(axes[f], out var s, out var t), Is.EqualTo(f));
                Assert.That((s, t), Is.EqualTo((0.5, 0.5)));
            }
            // +Z face: sc = x = −0.5, tc = −y = −0.5 at (−0.5, 0.5, 1), so up and to the left of forward is the top-left quarter.
            Assert.That(UnityCubemap.Face(new Vector3d(-0.5, 0.5, 1), out var s0, out var t0), Is.EqualTo(UnityCubemap.PositiveZ));
            Assert.That((s0, t0), Is.EqualTo((0.25, 0.25)));
            // +X face's right edge is −Z (left-handed: facing +X, the right hand points to −Z).
            Assert.That(UnityCubemap.Face(new Vector3d(1, 0, -0.999), out var s1, out _), Is.EqualTo(UnityCubemap.PositiveX));
            Assert.That(s1, Is.GreaterThan(0.99));
            foreach (var d in Directions())
            {
                var unity = BlenderConvention.ToUnity(d);
                var face = UnityCubemap.Face(unity, out var s, out var t);
                Near(UnityCubemap.Direction(face, s, t).Normalized(), unity, 1e-12, "face round trip");
            }
        }

        [Test]
        public void ACubemapResamplesToTheEquirectOfTheSameLight()
        {
            // Faces filled from a smooth function of the Unity direction; the equirect must show the same function of ours.
            const int size = 32;
            Func<Vector3d, double> light = unity => 1 + unity.X + 2 * unity.Y + 3 * unity.Z;
            var faces = new float[6][];
            for (var f = 0; f < 6; f++)
            {
                faces[f] = new float[size * size * 3];
                for (var row = 0; row < size; row++)
                    for (var column = 0; column < size; column++)
                    {
                        var value = (float)light(UnityCubemap.Direction(f, (column + 0.5) / size, (row + 0.5) / size).Normalized());
                        for (var c = 0; c < 3; c++) faces[f][(row * size + column) * 3 + c] = value;
                    }
            }
            var map = UnitySkybox.FromCubemap(faces, size, 64);
            var worst = 0.0;
            for (var row = 0; row < 32; row++)
                for (var column = 0; column < 64; column++)
                {
                    var expected = light(BlenderConvention.ToUnity(Equirect.PixelDirection(column, row, 64, 32)));
                    worst = Math.Max(worst, Math.Abs(map.Rgb[(row * 64 + column) * 3] - expected));
                }
            Assert.That(worst, Is.LessThan(0.1), "bilinear within a face, clamped at its edges");
        }

        [Test]
        public void DirectionsRoundTripThroughEveryTrainersConvention()
        {
            foreach (var d in Directions())
            {
                Equirect.Uv(d, out var u, out var v);
                // TensoIR (and R3DG, the same code): its grid_sample point is ours (phi is offset by 1e-6).
                LightConventions.TensoIrUv(d, out var tu, out var tv);
                Assert.That(Math.Min(Math.Abs(tu - u), 1 - Math.Abs(tu - u)), Is.LessThan(1e-9), "TensoIR u at " + d);
                Assert.That(tv, Is.EqualTo(v).Within(1e-6), "TensoIR v at " + d);
                // TensoIR's rotated lookup is Rz(−θ): the same sense as ours.
                foreach (var degrees in new[] { 0.0, 120, 240 })
                    Near(LightConventions.TensoIrRotatedLookup(d, degrees), Equirect.RotateZ(d, -degrees), 1e-12, "TensoIR rotation " + degrees);
                // NeRFactor: lat/lng round trip, and our u, v are its lng, lat.
                LightConventions.NerfactorLatLng(d, out var lat, out var lng);
                Assert.That(v, Is.EqualTo(0.5 - lat / Math.PI).Within(1e-12));
                Assert.That(Math.Min(Math.Abs(u - (0.5 - lng / (2 * Math.PI))), Math.Abs(Math.Abs(u - (0.5 - lng / (2 * Math.PI))) - 1)), Is.LessThan(1e-12));
                // Stanford-ORB: a quarter turn of columns, same rows, and back.
                LightConventions.StanfordOrbUv(d, out var ou, out var ov);
                Assert.That(Math.Abs(((ou - u) % 1 + 1) % 1 - 0.25), Is.LessThan(1e-9), "ORB u at " + d);
                Assert.That(ov, Is.EqualTo(v).Within(1e-12));
                Near(LightConventions.StanfordOrbDirection(ou, ov), d, 1e-9, "ORB round trip");
            }
            // NeRFactor's grid: row 0, column 0 of a 16×32 map is near the top and at lng just under π (our left edge).
            var first = LightConventions.NerfactorDirection(0, 0, 16, 32);
            Equirect.Uv(first, out var fu, out var fv);
            Assert.That(fu, Is.EqualTo(1.0 / 34).Within(1e-12), "(j + 1)·2π/(w + 2) from lng = π");
            Assert.That(fv, Is.EqualTo(1.0 / 18).Within(1e-12), "(i + 1)·π/(h + 2) from the top");
            // ORB's left column is +Z of its Y-up frame: our −Y.
            LightConventions.StanfordOrbUv(-Vector3d.UnitY, out var left, out _);
            Assert.That(left, Is.EqualTo(0).Within(1e-12));
            Assert.That(LightConventions.StanfordOrbRollColumns(128), Is.EqualTo(32));
        }
    }
}
