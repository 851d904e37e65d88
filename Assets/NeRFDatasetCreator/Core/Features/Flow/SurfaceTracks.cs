using System.Collections.Generic;
using System.Threading.Tasks;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Long tracks of a video (issue 37): the query points are the pixel centres (i·stride + 0.5, j·stride + 0.5) of the
    /// query frame whose ray meets the target; each keeps its triangle and barycentrics, so at every frame of the video it
    /// is the same surface point, projected into that frame's camera and tested for occlusion as <see cref="SurfaceFlow"/>
    /// does. Arrays are frame-major: <see cref="Xy"/>[(t·N + n)·2 + c].
    /// </summary>
    public sealed class SurfaceTracks
    {
        public int QueryFrame { get; private set; }
        public int Stride { get; private set; }
        public int Frames { get; private set; }
        public int Points { get; private set; }

        /// <summary>(x, y) of each query point in the query frame: continuous pixel coordinates.</summary>
        public float[] QueryXy { get; private set; }

        /// <summary>(x, y) per frame and point: where the point projects (NaN behind the camera).</summary>
        public float[] Xy { get; private set; }

        /// <summary><see cref="FlowState"/> per frame and point: Visible, Hidden or OutsideImage.</summary>
        public byte[] State { get; private set; }

        /// <summary>The surface point per frame and point, output frame and units.</summary>
        public float[] Positions { get; private set; }

        /// <param name="threads">Frames shared out among up to this many threads (a stack each): the same arrays for any count.</param>
        public static SurfaceTracks Of(FlowMeshes meshes, FlowVideo video, IReadOnlyList<FlowCamera> cameras, int queryFrame, int stride, int threads = 1)
        {
            var q = cameras[queryFrame];
            var queryStep = video.Frames[queryFrame].Step;
            var tree = meshes.Tree(queryStep);
            var tris = meshes.Triangles;
            var hits = new List<(double x, double y, int tri, double u, double v)>();
            for (var j = 0; j * stride < q.Height; j++)
                for (var i = 0; i * stride < q.Width; i++)
                {
                    double x = i * stride + 0.5, y = j * stride + 0.5;
                    q.Ray(x, y, out var dx, out var dy, out var dz);
                    var o = q.Centre;
                    if (tree.Intersect(o.X, o.Y, o.Z, dx, dy, dz, 0, double.PositiveInfinity, out var hit)) hits.Add((x, y, hit.Triangle, hit.U, hit.V));
                }
            int n = hits.Count, frames = video.Frames.Count;
            var result = new SurfaceTracks
            {
                QueryFrame = queryFrame, Stride = stride, Frames = frames, Points = n,
                QueryXy = new float[2 * n], Xy = new float[2 * n * frames], State = new byte[n * frames], Positions = new float[3 * n * frames],
            };
            for (var p = 0; p < n; p++)
            {
                result.QueryXy[2 * p] = (float)hits[p].x;
                result.QueryXy[2 * p + 1] = (float)hits[p].y;
            }
            // Each frame writes only its own slots (t·N …), so the frames may run on several threads.
            void Frame(int t)
            {
                var vertices = meshes.Vertices(video.Frames[t].Step);
                var atT = meshes.Tree(video.Frames[t].Step);
                var camera = cameras[t];
                var stack = atT.NewStack();
                var c = camera.Centre;
                for (var p = 0; p < n; p++)
                {
                    var h = hits[p];
                    int a = 3 * tris[3 * h.tri], b = 3 * tris[3 * h.tri + 1], e = 3 * tris[3 * h.tri + 2];
                    double w0 = 1 - h.u - h.v;
                    double px = w0 * vertices[a] + h.u * vertices[b] + h.v * vertices[e];
                    double py = w0 * vertices[a + 1] + h.u * vertices[b + 1] + h.v * vertices[e + 1];
                    double pz = w0 * vertices[a + 2] + h.u * vertices[b + 2] + h.v * vertices[e + 2];
                    var k = t * n + p;
                    result.Positions[3 * k] = (float)px;
                    result.Positions[3 * k + 1] = (float)py;
                    result.Positions[3 * k + 2] = (float)pz;
                    FlowState state;
                    if (!camera.Project(px, py, pz, out var x, out var y, out _))
                    {
                        x = y = double.NaN;
                        state = FlowState.OutsideImage;
                    }
                    else if (!camera.Inside(x, y)) state = FlowState.OutsideImage;
                    else
                    {
                        double rx = px - c.X, ry = py - c.Y, rz = pz - c.Z;
                        state = atT.Intersect(c.X, c.Y, c.Z, rx, ry, rz, 0, 1 - SurfaceFlow.HiddenTolerance, stack, out _) ? FlowState.Hidden : FlowState.Visible;
                    }
                    result.Xy[2 * k] = (float)x;
                    result.Xy[2 * k + 1] = (float)y;
                    result.State[k] = (byte)state;
                }
            }
            if (threads > 1) Parallel.For(0, frames, new ParallelOptions { MaxDegreeOfParallelism = threads }, Frame);
            else for (var t = 0; t < frames; t++) Frame(t);
            return result;
        }
    }
}
