using System;
using System.Collections.Generic;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The test suite's one analytic scene, and its one ray–sphere solver (<see cref="HitSphere"/>): spheres (one may be
    /// glass, partly transparent) and axis-aligned boxes, ray-traced exactly. The capture's test layout
    /// (<see cref="Layout"/>) is made in Unity's world and converted with the plan's own <see cref="SceneNormalisation"/>,
    /// so a dataset rendered from it (<see cref="AnalyticDataset"/>, through Core's ViewPipeline) is what a capture of that
    /// layout must give; its meshes are <see cref="AnalyticSceneMeshes"/>. The evaluation's unit sphere
    /// (<see cref="AnalyticSphereDataset"/>) is a scene of this class too. The one other scene the tests keep is
    /// <see cref="SphereScene"/>: the independent oracle of the COLMAP track tests (it writes its dataset by hand, not
    /// through Core's writers, with depths and masks of its own rounding), which casts its rays through this scene.
    /// </summary>
    sealed class AnalyticScene
    {
        public sealed class Sphere
        {
            public Vector3d Centre;
            public double Radius;
            public double[] Colour;
            public double Alpha = 1;
        }

        public sealed class Box
        {
            public Vector3d Min, Max;
            public double[] Colour;
        }

        public readonly List<Sphere> Spheres = new List<Sphere>();
        public readonly List<Box> Boxes = new List<Box>();

        /// <summary>
        /// The test layout in Unity's world around <paramref name="centre"/>: an opaque sphere up-left, a glass sphere to the
        /// right, a wide slab underneath (flat faces, and no up-down symmetry, so a flip shows); at <paramref name="time"/> in
        /// [0, 1] the opaque sphere moves 0.4 along Unity +X.
        /// </summary>
        public static AnalyticScene Layout(SceneNormalisation normalisation, Vector3d centre, double time = 0)
        {
            var s = normalisation.Scale;
            Vector3d Out(Vector3d offset) => normalisation.ApplyToUnityPoint(centre + offset);
            var scene = new AnalyticScene();
            scene.Spheres.Add(new Sphere { Centre = Out(OpaqueOffset(time)), Radius = OpaqueRadius * s, Colour = new[] { 0.8, 0.25, 0.1 } });
            scene.Spheres.Add(new Sphere { Centre = Out(GlassOffset), Radius = GlassRadius * s, Colour = new[] { 0.2, 0.4, 0.9 }, Alpha = 0.5 });
            var a = Out(SlabLow);
            var b = Out(SlabHigh);
            scene.Boxes.Add(new Box
            {
                Min = new Vector3d(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z)),
                Max = new Vector3d(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z)),
                Colour = new[] { 0.3, 0.7, 0.3 },
            });
            return scene;
        }

        /// <summary>The layout's opaque sphere: its centre's offset from the layout centre at normalised <paramref name="time"/> (Unity units), and its radius.</summary>
        public static Vector3d OpaqueOffset(double time) => new Vector3d(-0.45 + 0.4 * time, 0.35, -0.1);

        public const double OpaqueRadius = 0.45;

        /// <summary>The layout's glass sphere (alpha 0.5): offset and radius.</summary>
        public static readonly Vector3d GlassOffset = new Vector3d(0.55, 0.15, 0.25);

        public const double GlassRadius = 0.3;

        /// <summary>The layout's slab: the offsets of two opposite corners.</summary>
        public static readonly Vector3d SlabLow = new Vector3d(-0.9, -0.75, -0.6), SlabHigh = new Vector3d(0.9, -0.35, 0.5);

        /// <summary>A scene of one opaque sphere of <paramref name="radius"/> at <paramref name="centre"/> (white: the caller colours by normal).</summary>
        public static AnalyticScene OneSphere(Vector3d centre, double radius)
        {
            var scene = new AnalyticScene();
            scene.Spheres.Add(new Sphere { Centre = centre, Radius = radius, Colour = new[] { 1.0, 1.0, 1.0 } });
            return scene;
        }

        /// <summary>
        /// The one ray–sphere solver: the nearest root t &gt; <paramref name="after"/> of |o + t·d − c|² = r² (d need not be
        /// unit), or +∞ when the ray misses the sphere beyond <paramref name="after"/>.
        /// </summary>
        public static double HitSphere(Vector3d o, Vector3d d, Vector3d centre, double radius, double after)
        {
            var oc = o - centre;
            double a = Vector3d.Dot(d, d), b = Vector3d.Dot(oc, d), c = Vector3d.Dot(oc, oc) - radius * radius;
            var disc = b * b - a * c;
            if (disc < 0) return double.PositiveInfinity;
            var root = Math.Sqrt(disc);
            var near = (-b - root) / a;
            if (near > after) return near;
            var far = (-b + root) / a;
            return far > after ? far : double.PositiveInfinity;
        }

        /// <summary>The nearest hit along o + t·d (t &gt; 0) beyond <paramref name="after"/>: its t, normal, colour and alpha.</summary>
        public bool Trace(Vector3d o, Vector3d d, double after, out double t, out Vector3d normal, out double[] colour, out double alpha) =>
            Trace(o, d, after, out t, out normal, out colour, out alpha, out _);

        /// <summary>
        /// The objects' instance ids, as a capture with labels numbers them: spheres 1, 2…, then boxes (the layout's
        /// hierarchy order, <see cref="AnalyticDataset.LabelObjects"/>).
        /// </summary>
        public int ObjectCount => Spheres.Count + Boxes.Count;

        /// <summary><see cref="Trace(Vector3d, Vector3d, double, out double, out Vector3d, out double[], out double)"/> that also gives the hit object's instance id (0 for none).</summary>
        public bool Trace(Vector3d o, Vector3d d, double after, out double t, out Vector3d normal, out double[] colour, out double alpha, out int objectId)
        {
            objectId = 0;
            t = double.PositiveInfinity;
            normal = Vector3d.Zero;
            colour = null;
            alpha = 0;
            for (var index = 0; index < Spheres.Count; index++)
            {
                var s = Spheres[index];
                var hit = HitSphere(o, d, s.Centre, s.Radius, after);
                if (!(hit < t)) continue;
                t = hit;
                normal = (o + d * hit - s.Centre).Normalized();
                colour = s.Colour;
                alpha = s.Alpha;
                objectId = index + 1;
            }
            for (var index = 0; index < Boxes.Count; index++)
            {
                var box = Boxes[index];
                if (!Slab(o, d, box, out var near, out var far, out var axis, out var sign)) continue;
                var hit = near > after ? near : far;
                if (hit <= after || hit >= t) continue;
                t = hit;
                normal = axis == 0 ? new Vector3d(sign, 0, 0) : axis == 1 ? new Vector3d(0, sign, 0) : new Vector3d(0, 0, sign);
                if (hit == far) normal = -normal; // inside the box (never for the test cameras)
                colour = box.Colour;
                alpha = 1;
                objectId = Spheres.Count + index + 1;
            }
            // Geometry normals face the camera (two-sided surfaces are turned towards it: pixels.md §1).
            if (colour != null && Vector3d.Dot(normal, d) > 0) normal = -normal;
            return colour != null;
        }

        static bool Slab(Vector3d o, Vector3d d, Box box, out double near, out double far, out int axis, out double sign)
        {
            near = double.NegativeInfinity;
            far = double.PositiveInfinity;
            axis = 0;
            sign = 1;
            double[] oo = { o.X, o.Y, o.Z }, dd = { d.X, d.Y, d.Z }, lo = { box.Min.X, box.Min.Y, box.Min.Z }, hi = { box.Max.X, box.Max.Y, box.Max.Z };
            for (var k = 0; k < 3; k++)
            {
                if (Math.Abs(dd[k]) < 1e-15)
                {
                    if (oo[k] < lo[k] || oo[k] > hi[k]) return false;
                    continue;
                }
                double t1 = (lo[k] - oo[k]) / dd[k], t2 = (hi[k] - oo[k]) / dd[k];
                var s = -1.0;
                if (t1 > t2) { var x = t1; t1 = t2; t2 = x; s = 1; }
                if (t1 > near) { near = t1; axis = k; sign = s; }
                if (t2 < far) far = t2;
            }
            return near <= far && far > 0;
        }

        /// <summary>Points spread over every surface (by area, deterministic), as <c>points3d.ply</c> holds them.</summary>
        public List<CloudPoint> Surface(int count)
        {
            var random = new Random(7);
            var points = new List<CloudPoint>();
            var areas = new List<double>();
            foreach (var s in Spheres) areas.Add(4 * Math.PI * s.Radius * s.Radius);
            foreach (var b in Boxes)
            {
                var e = b.Max - b.Min;
                areas.Add(2 * (e.X * e.Y + e.Y * e.Z + e.X * e.Z));
            }
            var total = 0.0;
            foreach (var a in areas) total += a;
            for (var n = 0; n < count; n++)
            {
                var pick = random.NextDouble() * total;
                var k = 0;
                while (k < areas.Count - 1 && pick > areas[k]) pick -= areas[k++];
                if (k < Spheres.Count)
                {
                    var s = Spheres[k];
                    var z = 2 * random.NextDouble() - 1;
                    var phi = 2 * Math.PI * random.NextDouble();
                    var r = Math.Sqrt(1 - z * z);
                    var dir = new Vector3d(r * Math.Cos(phi), r * Math.Sin(phi), z);
                    points.Add(new CloudPoint(s.Centre + dir * s.Radius, dir, 200, 100, 50));
                }
                else
                {
                    var b = Boxes[k - Spheres.Count];
                    var face = random.Next(6);
                    var axis = face / 2;
                    double u = random.NextDouble(), v = random.NextDouble();
                    double[] p = { b.Min.X + u * (b.Max.X - b.Min.X), b.Min.Y + v * (b.Max.Y - b.Min.Y), b.Min.Z + random.NextDouble() * (b.Max.Z - b.Min.Z) };
                    double[] lo = { b.Min.X, b.Min.Y, b.Min.Z }, hi = { b.Max.X, b.Max.Y, b.Max.Z };
                    p[axis] = face % 2 == 0 ? lo[axis] : hi[axis];
                    var normal = new double[3];
                    normal[axis] = face % 2 == 0 ? -1 : 1;
                    points.Add(new CloudPoint(new Vector3d(p[0], p[1], p[2]), new Vector3d(normal[0], normal[1], normal[2]), 60, 180, 60));
                }
            }
            return points;
        }
    }
}
