using System;
using System.Threading.Tasks;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Exact optical flow, scene flow and occlusion of a deforming mesh between two times (issue 37). The target's mesh
    /// at both times has one topology (the geometry pack's per-step meshes): a pixel's ray at time t hits triangle i at
    /// barycentrics (u, v); the same (i, u, v) at time t′ is the same surface point, which is projected into the camera at
    /// t′. Flow is (x′ − x, y′ − y) in pixels, x to the right and y down, from the pixel centre (u + 0.5, v + 0.5); scene
    /// flow is P′ − P in output units. The point is hidden at t′ when the ray from the camera at t′ towards it meets the
    /// mesh at t′ more than <see cref="HiddenTolerance"/> of the distance before it.
    /// </summary>
    public sealed class SurfaceFlow
    {
        /// <summary>
        /// How much nearer (relative to the distance) another surface must be to hide a point: 1e-6 — far above the
        /// rounding of a cast in doubles (~1e-15 relative) and below any real gap between two surfaces at capture scales.
        /// </summary>
        public const double HiddenTolerance = 1e-6;

        readonly double[] _from;
        readonly double[] _to;
        readonly int[] _triangles;
        readonly TriangleBvh _atFrom;
        readonly TriangleBvh _atTo;

        /// <param name="verticesFrom">The mesh's vertices at t (x, y, z each, output frame).</param>
        /// <param name="verticesTo">The same vertices at t′, in the same order.</param>
        /// <param name="triangles">Three vertex indices per triangle, shared by both times.</param>
        public SurfaceFlow(double[] verticesFrom, double[] verticesTo, int[] triangles)
        {
            if (verticesFrom == null || verticesTo == null || verticesFrom.Length != verticesTo.Length)
                throw new ArgumentException("The mesh at both times needs the same vertices: " + (verticesFrom?.Length / 3) + " and " + (verticesTo?.Length / 3) + " given (a changing topology cannot carry flow).");
            _from = verticesFrom;
            _to = verticesTo;
            _triangles = triangles;
            _atFrom = TriangleBvh.Build(verticesFrom, triangles);
            _atTo = TriangleBvh.Build(verticesTo, triangles);
        }

        /// <summary>The same, with each time's tree already built (<see cref="FlowMeshes"/> builds one per step and shares it).</summary>
        public SurfaceFlow(double[] verticesFrom, TriangleBvh atFrom, double[] verticesTo, TriangleBvh atTo, int[] triangles)
        {
            if (verticesFrom == null || verticesTo == null || verticesFrom.Length != verticesTo.Length)
                throw new ArgumentException("The mesh at both times needs the same vertices: " + (verticesFrom?.Length / 3) + " and " + (verticesTo?.Length / 3) + " given (a changing topology cannot carry flow).");
            _from = verticesFrom;
            _to = verticesTo;
            _triangles = triangles;
            _atFrom = atFrom ?? throw new ArgumentNullException(nameof(atFrom));
            _atTo = atTo ?? throw new ArgumentNullException(nameof(atTo));
        }

        /// <summary>
        /// The flow of continuous pixel (x, y) of <paramref name="from"/> into <paramref name="to"/>: false (and
        /// <see cref="FlowState.NoSurface"/>) when its ray meets no surface. Not thread-safe (the trees' stacks).
        /// </summary>
        public FlowState At(FlowCamera from, FlowCamera to, double x, double y, out FlowSample sample) =>
            At(from, to, x, y, null, null, out sample);

        /// <summary>
        /// The same with the caller's traversal stacks for the trees at t and t′ (<see cref="TriangleBvh.NewStack"/>; null
        /// = the trees' own): a thread with stacks of its own may call this while others do.
        /// </summary>
        public FlowState At(FlowCamera from, FlowCamera to, double x, double y, int[] stackFrom, int[] stackTo, out FlowSample sample)
        {
            sample = default;
            from.Ray(x, y, out var dx, out var dy, out var dz);
            var o = from.Centre;
            if (!_atFrom.Intersect(o.X, o.Y, o.Z, dx, dy, dz, 0, double.PositiveInfinity, stackFrom, out var hit)) return FlowState.NoSurface;
            int a = 3 * _triangles[3 * hit.Triangle], b = 3 * _triangles[3 * hit.Triangle + 1], c = 3 * _triangles[3 * hit.Triangle + 2];
            double w0 = 1 - hit.U - hit.V, w1 = hit.U, w2 = hit.V;
            sample.Px = w0 * _from[a] + w1 * _from[b] + w2 * _from[c];
            sample.Py = w0 * _from[a + 1] + w1 * _from[b + 1] + w2 * _from[c + 1];
            sample.Pz = w0 * _from[a + 2] + w1 * _from[b + 2] + w2 * _from[c + 2];
            sample.Qx = w0 * _to[a] + w1 * _to[b] + w2 * _to[c];
            sample.Qy = w0 * _to[a + 1] + w1 * _to[b + 1] + w2 * _to[c + 1];
            sample.Qz = w0 * _to[a + 2] + w1 * _to[b + 2] + w2 * _to[c + 2];
            sample.Triangle = hit.Triangle;
            if (!to.Project(sample.Qx, sample.Qy, sample.Qz, out var x2, out var y2, out _))
            {
                sample.Dx = sample.Dy = double.NaN;
                return FlowState.OutsideImage;
            }
            sample.Dx = x2 - x;
            sample.Dy = y2 - y;
            if (!to.Inside(x2, y2)) return FlowState.OutsideImage;
            // Occlusion: the ray from the camera at t′ to the point, t in (0, 1); a hit before 1 − tolerance hides it.
            var c2 = to.Centre;
            double rx = sample.Qx - c2.X, ry = sample.Qy - c2.Y, rz = sample.Qz - c2.Z;
            return _atTo.Intersect(c2.X, c2.Y, c2.Z, rx, ry, rz, 0, 1 - HiddenTolerance, stackTo, out _) ? FlowState.Hidden : FlowState.Visible;
        }

        /// <summary>Flow for every pixel centre of <paramref name="from"/>'s image into <paramref name="to"/>, on one thread.</summary>
        public FlowField Image(FlowCamera from, FlowCamera to) => Image(from, to, 1);

        /// <summary>
        /// The same on up to <paramref name="threads"/> threads, rows shared out among them, each with its own traversal
        /// stacks (the trees are only read). Every pixel is computed alone, so the field is the same for any thread count.
        /// </summary>
        public FlowField Image(FlowCamera from, FlowCamera to, int threads)
        {
            int w = from.Width, h = from.Height;
            var field = new FlowField(w, h);
            if (threads <= 1)
            {
                int[] stackFrom = _atFrom.NewStack(), stackTo = _atTo.NewStack();
                for (var v = 0; v < h; v++) Row(from, to, field, v, stackFrom, stackTo);
                return field;
            }
            Parallel.For(0, h, new ParallelOptions { MaxDegreeOfParallelism = threads },
                () => new[] { _atFrom.NewStack(), _atTo.NewStack() },
                (v, _, stacks) => { Row(from, to, field, v, stacks[0], stacks[1]); return stacks; },
                _ => { });
            return field;
        }

        void Row(FlowCamera from, FlowCamera to, FlowField field, int v, int[] stackFrom, int[] stackTo)
        {
            var w = field.Width;
            for (var u = 0; u < w; u++)
            {
                var p = v * w + u;
                var state = At(from, to, u + 0.5, v + 0.5, stackFrom, stackTo, out var s);
                field.State[p] = (byte)state;
                if (state == FlowState.NoSurface)
                {
                    field.Flow[2 * p] = field.Flow[2 * p + 1] = float.NaN;
                    field.SceneFlow[3 * p] = field.SceneFlow[3 * p + 1] = field.SceneFlow[3 * p + 2] = float.NaN;
                    continue;
                }
                field.Flow[2 * p] = (float)s.Dx;
                field.Flow[2 * p + 1] = (float)s.Dy;
                field.SceneFlow[3 * p] = (float)(s.Qx - s.Px);
                field.SceneFlow[3 * p + 1] = (float)(s.Qy - s.Py);
                field.SceneFlow[3 * p + 2] = (float)(s.Qz - s.Pz);
            }
        }
    }
}
