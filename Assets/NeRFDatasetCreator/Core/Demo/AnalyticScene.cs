using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The one analytic scene of the test suite and of <c>nerf-dataset demo</c> (Documentation~/maintainers/demo.md),
    /// and its one ray–sphere solver (<see cref="HitSphere"/>): spheres (one may be glass, partly transparent) and
    /// axis-aligned boxes, ray-traced exactly. The layout (<see cref="Layout"/>) is made in Unity's world and converted
    /// with the plan's own <see cref="SceneNormalisation"/>, so a dataset rendered from it (<see cref="AnalyticDataset"/>,
    /// through Core's ViewPipeline) is what a capture of that layout must give; its meshes are
    /// <see cref="AnalyticSceneMeshes"/>. The tests' layout is untextured (their pinned bytes were made so); the demo's
    /// (<see cref="AnalyticLook.Demo"/>) adds procedural texture, which a trainer needs to place its surfaces, and a
    /// fourth object. The test suite keeps one other scene, <c>Tests/Core/TestSupport/SphereScene</c>: the independent
    /// oracle of the COLMAP track tests, which casts its rays through this scene.
    /// </summary>
    public sealed class AnalyticScene
    {
        public sealed class Sphere
        {
            public Vector3d Centre;
            public double Radius;
            public double[] Colour;
            public double Alpha = 1;

            /// <summary>Null: one colour. Else the second colour of a latitude–longitude checker (<see cref="Bands"/> × 2·Bands cells).</summary>
            public double[] Colour2;
            public int Bands = 6;
        }

        public sealed class Box
        {
            public Vector3d Min, Max;
            public double[] Colour;

            /// <summary>Null: one colour. Else the second colour of a 3-D checker of cubes of side <see cref="Cell"/> from <see cref="Min"/>.</summary>
            public double[] Colour2;
            public double Cell = 1;
        }

        public readonly List<Sphere> Spheres = new List<Sphere>();
        public readonly List<Box> Boxes = new List<Box>();

        /// <summary>
        /// The layout in Unity's world around <paramref name="centre"/>: an opaque sphere up-left, a glass sphere to the
        /// right, a wide slab underneath (flat faces, and no up-down symmetry, so a flip shows); at <paramref name="time"/> in
        /// [0, 1] the opaque sphere moves 0.4 along Unity +X. <see cref="AnalyticLook.Demo"/> textures every object and puts
        /// a crate on the slab, in front of the glass sphere (no left–right or front–back symmetry either).
        /// </summary>
        public static AnalyticScene Layout(SceneNormalisation normalisation, Vector3d centre, double time = 0, AnalyticLook look = AnalyticLook.Test)
        {
            var s = normalisation.Scale;
            var demo = look == AnalyticLook.Demo;
            Vector3d Out(Vector3d offset) => normalisation.ApplyToUnityPoint(centre + offset);
            var scene = new AnalyticScene();
            scene.Spheres.Add(new Sphere { Centre = Out(OpaqueOffset(time)), Radius = OpaqueRadius * s, Colour = new[] { 0.8, 0.25, 0.1 },
                Colour2 = demo ? new[] { 0.95, 0.8, 0.2 } : null, Bands = 6 });
            scene.Spheres.Add(new Sphere { Centre = Out(GlassOffset), Radius = GlassRadius * s, Colour = new[] { 0.2, 0.4, 0.9 }, Alpha = 0.5,
                Colour2 = demo ? new[] { 0.85, 0.9, 1.0 } : null, Bands = 4 });
            scene.Boxes.Add(BoxBetween(Out(SlabLow), Out(SlabHigh), new[] { 0.3, 0.7, 0.3 }, demo ? new[] { 0.9, 0.9, 0.8 } : null, 0.2 * s));
            if (demo) scene.Boxes.Add(BoxBetween(Out(CrateLow), Out(CrateHigh), new[] { 0.55, 0.35, 0.15 }, new[] { 0.15, 0.1, 0.35 }, 0.1 * s));
            return scene;
        }

        /// <summary>The axis-aligned box with corners <paramref name="a"/> and <paramref name="b"/> (output world: the normalisation may swap and flip axes).</summary>
        static Box BoxBetween(Vector3d a, Vector3d b, double[] colour, double[] colour2, double cell) => new Box
        {
            Min = new Vector3d(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z)),
            Max = new Vector3d(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z)),
            Colour = colour,
            Colour2 = colour2,
            Cell = cell,
        };

        /// <summary>The layout's opaque sphere: its centre's offset from the layout centre at normalised <paramref name="time"/> (Unity units), and its radius.</summary>
        public static Vector3d OpaqueOffset(double time) => new Vector3d(-0.45 + 0.4 * time, 0.35, -0.1);

        public const double OpaqueRadius = 0.45;

        /// <summary>The layout's glass sphere (alpha 0.5): offset and radius.</summary>
        public static readonly Vector3d GlassOffset = new Vector3d(0.55, 0.15, 0.25);

        public const double GlassRadius = 0.3;

        /// <summary>The layout's slab: the offsets of two opposite corners.</summary>
        public static readonly Vector3d SlabLow = new Vector3d(-0.9, -0.75, -0.6), SlabHigh = new Vector3d(0.9, -0.35, 0.5);

        /// <summary>The demo's crate on the slab (<see cref="AnalyticLook.Demo"/>): the offsets of two opposite corners; it sits on the slab's top face.</summary>
        public static readonly Vector3d CrateLow = new Vector3d(0.05, -0.35, -0.5), CrateHigh = new Vector3d(0.45, 0.05, -0.15);

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
                colour = ColourOf(s, normal);
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
                colour = ColourOf(box, o + d * hit);
                alpha = 1;
                objectId = Spheres.Count + index + 1;
            }
            // Geometry normals face the camera (two-sided surfaces are turned towards it: pixels.md §1).
            if (colour != null && Vector3d.Dot(normal, d) > 0) normal = -normal;
            return colour != null;
        }

        /// <summary>
        /// The sphere's colour at the point in direction <paramref name="outward"/> from its centre: a checker of latitude
        /// bands and longitude sectors (it moves with the sphere, so a dynamic scene's texture stays on its object).
        /// </summary>
        public static double[] ColourOf(Sphere sphere, Vector3d outward)
        {
            if (sphere.Colour2 == null) return sphere.Colour;
            // Output world: Blender's axes, +Z up.
            var latitude = Math.Acos(Math.Max(-1, Math.Min(1, outward.Z)));
            var longitude = Math.Atan2(outward.Y, outward.X) + Math.PI;
            var band = (int)Math.Floor(latitude / Math.PI * sphere.Bands);
            var sector = (int)Math.Floor(longitude / (2 * Math.PI) * 2 * sphere.Bands);
            return ((band + sector) & 1) == 0 ? sphere.Colour : sphere.Colour2;
        }

        /// <summary>The box's colour at <paramref name="point"/> on its surface: a 3-D checker of cubes from its minimum corner.</summary>
        public static double[] ColourOf(Box box, Vector3d point)
        {
            if (box.Colour2 == null) return box.Colour;
            var p = point - box.Min;
            // A point on a face lies on a cell boundary along that face's axis: a tiny inward nudge keeps the face one colour per cell.
            var c = box.Cell;
            long Cell(double v, double size) => (long)Math.Floor(Math.Min(Math.Max(v, 1e-9), size - 1e-9) / c);
            var e = box.Max - box.Min;
            return ((Cell(p.X, e.X) + Cell(p.Y, e.Y) + Cell(p.Z, e.Z)) & 1) == 0 ? box.Colour : box.Colour2;
        }

        /// <summary>The ray's entry (near) and exit (far) parameters through the box, the axis and outward sign of the entry face.</summary>
        static bool Slab(Vector3d o, Vector3d d, Box box, out double near, out double far, out int axis, out double sign)
        {
            near = double.NegativeInfinity;
            far = double.PositiveInfinity;
            axis = 0;
            sign = 1;
            // Per axis, without arrays: this runs for every box on every ray of a dataset.
            return SlabAxis(o.X, d.X, box.Min.X, box.Max.X, 0, ref near, ref far, ref axis, ref sign)
                   && SlabAxis(o.Y, d.Y, box.Min.Y, box.Max.Y, 1, ref near, ref far, ref axis, ref sign)
                   && SlabAxis(o.Z, d.Z, box.Min.Z, box.Max.Z, 2, ref near, ref far, ref axis, ref sign)
                   && near <= far && far > 0;
        }

        /// <summary>One axis of <see cref="Slab"/>: false when the ray runs parallel to it outside the box.</summary>
        static bool SlabAxis(double o, double d, double lo, double hi, int k, ref double near, ref double far, ref int axis, ref double sign)
        {
            if (Math.Abs(d) < 1e-15) return !(o < lo || o > hi);
            double t1 = (lo - o) / d, t2 = (hi - o) / d;
            var s = -1.0;
            if (t1 > t2) { var x = t1; t1 = t2; t2 = x; s = 1; }
            if (t1 > near) { near = t1; axis = k; sign = s; }
            if (t2 < far) far = t2;
            return true;
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
                    if (s.Colour2 == null) points.Add(new CloudPoint(s.Centre + dir * s.Radius, dir, 200, 100, 50));
                    else points.Add(Coloured(s.Centre + dir * s.Radius, dir, ColourOf(s, dir)));
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
                    var point = new Vector3d(p[0], p[1], p[2]);
                    if (b.Colour2 == null) points.Add(new CloudPoint(point, new Vector3d(normal[0], normal[1], normal[2]), 60, 180, 60));
                    else points.Add(Coloured(point, new Vector3d(normal[0], normal[1], normal[2]), ColourOf(b, point)));
                }
            }
            return points;
        }

        /// <summary>A textured scene's point: its albedo, sRGB-encoded (what 3DGS starts its Gaussians' colours from).</summary>
        static CloudPoint Coloured(Vector3d point, Vector3d normal, double[] colour) =>
            new CloudPoint(point, normal, Srgb.EncodeByteExact(colour[0]), Srgb.EncodeByteExact(colour[1]), Srgb.EncodeByteExact(colour[2]));
    }

    /// <summary>How <see cref="AnalyticScene.Layout"/> looks: the tests' plain layout, or the demo's textured one with a crate.</summary>
    public enum AnalyticLook
    {
        Test,
        Demo,
    }
}
