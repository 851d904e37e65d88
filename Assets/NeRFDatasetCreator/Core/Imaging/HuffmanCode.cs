using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Length-limited Huffman codes for DEFLATE (RFC 1951 §3.2.2): code lengths from symbol counts, then the
    /// canonical codes those lengths define, bit-reversed because DEFLATE sends Huffman codes most significant bit
    /// first into a stream that is otherwise packed least significant bit first.
    /// </summary>
    public static class HuffmanCode
    {
        /// <summary>
        /// Writes into <paramref name="lengths"/>[0…count) an optimal prefix code's lengths for
        /// <paramref name="counts"/>, none longer than <paramref name="maxLength"/>; unused symbols get 0. A lone
        /// used symbol gets length 1, and so does a second, unused one. When the optimal code is too deep, the counts are halved (keeping every used
        /// symbol at least 1) and the code rebuilt: simple, always terminates (equal counts give a balanced tree),
        /// and costs almost nothing because the tables are small and deep codes only arise for very rare symbols.
        /// </summary>
        public static void BuildLengths(int[] counts, int count, int maxLength, byte[] lengths)
        {
            Array.Clear(lengths, 0, count);
            var keys = new long[count];
            int used = 0;
            for (int s = 0; s < count; s++)
                if (counts[s] > 0) keys[used++] = ((long)counts[s] << 16) | (uint)s;
            if (used == 0) return;
            if (used == 1)
            {
                // A one-symbol code is incomplete, which zlib refuses for the code-length code: add an unused partner.
                int only = (int)(keys[0] & 0xFFFF);
                lengths[only] = 1;
                lengths[only == 0 ? 1 : 0] = 1;
                return;
            }
            Array.Sort(keys, 0, used);
            var weights = new long[used];
            for (int i = 0; i < used; i++) weights[i] = keys[i] >> 16;
            var depths = new int[used];
            while (!TryDepths(weights, used, maxLength, depths))
                for (int i = 0; i < used; i++) weights[i] = (weights[i] + 1) >> 1;
            for (int i = 0; i < used; i++) lengths[keys[i] & 0xFFFF] = (byte)depths[i];
        }

        /// <summary>
        /// Huffman's construction with two queues over weights sorted ascending (leaves, then internal nodes in the
        /// order they are made, which is also ascending); false when a leaf ends up deeper than the limit.
        /// </summary>
        static bool TryDepths(long[] weights, int n, int maxLength, int[] depths)
        {
            // Sorting by (weight, symbol) kept leaves ascending; halving keeps that order.
            var nodeWeight = new long[n - 1];
            var parent = new int[2 * n - 1]; // leaves 0…n−1, internal nodes n…2n−2
            int leaf = 0, made = 0, taken = 0;
            for (int k = 0; k < n - 1; k++)
            {
                int first = Smallest(weights, n, nodeWeight, ref leaf, ref taken, made);
                int second = Smallest(weights, n, nodeWeight, ref leaf, ref taken, made);
                nodeWeight[k] = Weight(weights, nodeWeight, n, first) + Weight(weights, nodeWeight, n, second);
                parent[first] = n + k;
                parent[second] = n + k;
                made++;
            }
            var depth = new int[2 * n - 1];
            int root = 2 * n - 2;
            depth[root] = 0;
            for (int node = root - 1; node >= 0; node--) depth[node] = depth[parent[node]] + 1;
            bool fits = true;
            for (int i = 0; i < n; i++)
            {
                depths[i] = depth[i];
                if (depth[i] > maxLength) fits = false;
            }
            return fits;
        }

        static int Smallest(long[] weights, int n, long[] nodeWeight, ref int leaf, ref int taken, int made)
        {
            // Ties go to the leaf, which keeps the tree shallower.
            if (leaf < n && (taken >= made || weights[leaf] <= nodeWeight[taken])) return leaf++;
            return n + taken++;
        }

        static long Weight(long[] weights, long[] nodeWeight, int n, int node) => node < n ? weights[node] : nodeWeight[node - n];

        /// <summary>
        /// The canonical code of every symbol with a non-zero length (RFC 1951 §3.2.2), bit-reversed so that it can
        /// be OR-ed into a least-significant-bit-first stream as it is.
        /// </summary>
        public static void BuildCodes(byte[] lengths, int count, int[] codes)
        {
            var perLength = new int[16];
            for (int s = 0; s < count; s++) perLength[lengths[s]]++;
            perLength[0] = 0;
            var next = new int[16];
            int code = 0;
            for (int bits = 1; bits < 16; bits++)
            {
                code = (code + perLength[bits - 1]) << 1;
                next[bits] = code;
            }
            for (int s = 0; s < count; s++)
            {
                int length = lengths[s];
                codes[s] = length == 0 ? 0 : Reverse(next[length]++, length);
            }
        }

        static int Reverse(int code, int length)
        {
            int reversed = 0;
            for (int i = 0; i < length; i++, code >>= 1) reversed = (reversed << 1) | (code & 1);
            return reversed;
        }
    }
}
