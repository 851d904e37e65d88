using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A k-d tree over 3-D points for exact nearest-neighbour queries (Friedman, Bentley and Finkel 1977): split at the
    /// median of the widest axis until at most <see cref="LeafSize"/> points remain, points stored in tree order for
    /// locality; a query descends to the nearer side first and visits the other only when the splitting plane is closer
    /// than the best distance so far. Build O(n log n), a query O(log n) on surface-like data. Coordinates are floats
    /// (the clouds' own precision); distances are computed in double.
    /// </summary>
    public sealed class PointKdTree
    {
        public const int LeafSize = 8;

        readonly float[] xs, ys, zs;
        readonly int[] order;
        // Node arrays: a leaf has axis −1 and the point range [start, end); an inner node has children left/right.
        int[] nodeStart, nodeEnd, nodeLeft, nodeRight;
        sbyte[] nodeAxis;
        float[] nodeSplit;
        int nodeCount;
        readonly int[] stack = new int[128];
        readonly double[] stackDistance = new double[128];

        /// <param name="xyz">x, y, z per point (3n floats); not kept.</param>
        public PointKdTree(float[] xyz)
        {
            if (xyz == null || xyz.Length % 3 != 0) throw new ArgumentException("Pass three coordinates per point.", nameof(xyz));
            var n = xyz.Length / 3;
            if (n == 0) throw new ArgumentException("The tree needs at least one point.", nameof(xyz));
            // A NaN or infinite coordinate would send the median selection past the array's ends.
            for (var i = 0; i < xyz.Length; i++)
                if (float.IsNaN(xyz[i]) || float.IsInfinity(xyz[i])) throw new ArgumentException("Coordinate " + i + " is not finite; the tree needs finite points.", nameof(xyz));
            Count = n;
            order = new int[n];
            for (var i = 0; i < n; i++) order[i] = i;
            var capacity = Math.Max(1, 2 * (n / LeafSize + 1) * 2);
            nodeStart = new int[capacity];
            nodeEnd = new int[capacity];
            nodeLeft = new int[capacity];
            nodeRight = new int[capacity];
            nodeAxis = new sbyte[capacity];
            nodeSplit = new float[capacity];
            Build(xyz, n);
            xs = new float[n];
            ys = new float[n];
            zs = new float[n];
            for (var i = 0; i < n; i++)
            {
                var p = order[i];
                xs[i] = xyz[3 * p];
                ys[i] = xyz[3 * p + 1];
                zs[i] = xyz[3 * p + 2];
            }
        }

        public int Count { get; }

        /// <summary>
        /// The point stored at <paramref name="position"/> (0 … Count − 1) in tree order, which is spatially coherent:
        /// querying another tree with the points in this order keeps its nodes in cache.
        /// </summary>
        public void PointAt(int position, out double x, out double y, out double z)
        {
            x = xs[position];
            y = ys[position];
            z = zs[position];
        }

        /// <summary>The input index of the point stored at <paramref name="position"/>.</summary>
        public int OriginalIndex(int position) => order[position];

        void Build(float[] xyz, int n)
        {
            var work = new int[64];
            var top = 0;
            nodeCount = 1;
            nodeStart[0] = 0;
            nodeEnd[0] = n;
            work[top++] = 0;
            while (top > 0)
            {
                var node = work[--top];
                int start = nodeStart[node], end = nodeEnd[node];
                if (end - start <= LeafSize)
                {
                    nodeAxis[node] = -1;
                    continue;
                }
                float minX = float.MaxValue, minY = float.MaxValue, minZ = float.MaxValue, maxX = float.MinValue, maxY = float.MinValue, maxZ = float.MinValue;
                for (var i = start; i < end; i++)
                {
                    var p = 3 * order[i];
                    float x = xyz[p], y = xyz[p + 1], z = xyz[p + 2];
                    if (x < minX) minX = x;
                    if (x > maxX) maxX = x;
                    if (y < minY) minY = y;
                    if (y > maxY) maxY = y;
                    if (z < minZ) minZ = z;
                    if (z > maxZ) maxZ = z;
                }
                float ex = maxX - minX, ey = maxY - minY, ez = maxZ - minZ;
                var axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
                if (Math.Max(ex, Math.Max(ey, ez)) == 0)
                {
                    nodeAxis[node] = -1; // all points equal: one leaf, however many
                    continue;
                }
                var mid = (start + end) / 2;
                Select(xyz, axis, start, end - 1, mid);
                EnsureCapacity(nodeCount + 2);
                int left = nodeCount++, right = nodeCount++;
                nodeAxis[node] = (sbyte)axis;
                nodeSplit[node] = xyz[3 * order[mid] + axis];
                nodeLeft[node] = left;
                nodeRight[node] = right;
                nodeStart[left] = start;
                nodeEnd[left] = mid;
                nodeStart[right] = mid;
                nodeEnd[right] = end;
                if (top + 2 > work.Length) Array.Resize(ref work, work.Length * 2);
                work[top++] = left;
                work[top++] = right;
            }
        }

        void EnsureCapacity(int needed)
        {
            if (needed <= nodeStart.Length) return;
            var size = Math.Max(needed, nodeStart.Length * 2);
            Array.Resize(ref nodeStart, size);
            Array.Resize(ref nodeEnd, size);
            Array.Resize(ref nodeLeft, size);
            Array.Resize(ref nodeRight, size);
            Array.Resize(ref nodeAxis, size);
            Array.Resize(ref nodeSplit, size);
        }

        /// <summary>Quickselect (Hoare): puts the k-th smallest coordinate on <paramref name="axis"/> at k, smaller left, larger right.</summary>
        void Select(float[] xyz, int axis, int left, int right, int k)
        {
            while (right > left)
            {
                var pivot = xyz[3 * order[(left + right) >> 1] + axis];
                int i = left, j = right;
                while (i <= j)
                {
                    while (xyz[3 * order[i] + axis] < pivot) i++;
                    while (xyz[3 * order[j] + axis] > pivot) j--;
                    if (i <= j)
                    {
                        var t = order[i];
                        order[i] = order[j];
                        order[j] = t;
                        i++;
                        j--;
                    }
                }
                if (k <= j) right = j;
                else if (k >= i) left = i;
                else return;
            }
        }

        /// <summary>The squared distance from (x, y, z) to the nearest point of the tree.</summary>
        public double NearestDistanceSquared(double x, double y, double z) => Nearest(x, y, z, out _);

        /// <summary>The squared distance to the nearest point, and that point's index in the input array.</summary>
        public double Nearest(double x, double y, double z, out int index)
        {
            var best = double.MaxValue;
            var bestIndex = -1;
            var top = 0;
            stack[top] = 0;
            stackDistance[top++] = 0;
            while (top > 0)
            {
                top--;
                if (stackDistance[top] >= best) continue;
                var node = stack[top];
                while (nodeAxis[node] >= 0)
                {
                    var axis = nodeAxis[node];
                    var diff = (axis == 0 ? x : axis == 1 ? y : z) - nodeSplit[node];
                    int near, far;
                    if (diff < 0) { near = nodeLeft[node]; far = nodeRight[node]; }
                    else { near = nodeRight[node]; far = nodeLeft[node]; }
                    var planeDistance = diff * diff;
                    if (planeDistance < best)
                    {
                        stack[top] = far;
                        stackDistance[top++] = planeDistance;
                    }
                    node = near;
                }
                for (int i = nodeStart[node], end = nodeEnd[node]; i < end; i++)
                {
                    double dx = xs[i] - x, dy = ys[i] - y, dz = zs[i] - z;
                    var d = dx * dx + dy * dy + dz * dz;
                    if (d < best)
                    {
                        best = d;
                        bestIndex = i;
                    }
                }
            }
            index = order[bestIndex];
            return best;
        }
    }
}
