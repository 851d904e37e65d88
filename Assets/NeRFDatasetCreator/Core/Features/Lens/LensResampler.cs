using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Stage 2 of the per-view image stages (after motion blur, before matting and downsampling): the wide pinhole
    /// raw frame (<see cref="LensCapture.WideRender"/>, at supersampling k) resampled into the distorted raw frame at
    /// the output's supersampled size (output × k, same k), so everything after it is unchanged. Each output sample
    /// reads the wide render where <see cref="LensSampleMap"/> says its ray lands:
    /// <list type="bullet">
    /// <item>Colour: bilinear, on the values as rendered. The matting pair (over black, over white) is interpolated as
    /// a pair with the same weights, which keeps out = F + T·B exact (a bilinear mix of two renders of that form has
    /// that form), i.e. premultiplied colour and transmission are what is interpolated, never straight colour across an
    /// edge. In a Linear project these values are linear light. In a Gamma project the GPU blended gamma-space values,
    /// and the pair's relation only holds there, so they are interpolated as they are. An sRGB-byte colour pass is
    /// decoded to linear light first and handed on as <see cref="RawFrame.ColorLinear"/> (no second 8-bit rounding).
    /// Bilinear, not a wider kernel: the wide render is at least as dense as the output everywhere
    /// (<see cref="LensPinholeCover"/>), so each output sample needs only its neighbourhood, and the k×k box filter that
    /// follows does the anti-aliasing, as it does for an undistorted capture.</item>
    /// <item>Depth: z along the camera axis. The output pixel's ray and the wide sample's ray are the same ray of the same
    /// camera (shared centre and axes), and z is a property of the surface point, not of the projection, so the wide
    /// render's z at that ray is the output's z with no conversion. It is never blended across a discontinuity: where
    /// the four neighbours are all surface and either within <see cref="SmoothDepth"/> of each other or changing evenly
    /// (each step across the cell at most <see cref="EvenStep"/>× the steps just outside it, so a steep but smooth
    /// surface counts and a step does not), 1/z is interpolated bilinearly (exact on a plane, whose 1/z is affine in
    /// pinhole image coordinates); anywhere else the nearest sample's z is taken as it is.</item>
    /// <item>Normals: the nearest sample's (a world-frame normal of the surface point on that ray; the two cameras share
    /// their rotation, so no frame changes), never blended.</item>
    /// <item>Mask: hit or not per sample, as the mask pass renders it (no MSAA) — the half-coverage contour of the bilinear
    /// interpolant, so the edge is placed to a fraction of a wide sample; the k×k mean after it is the pixel's coverage as
    /// without a lens, and the label ids agree with it exactly.</item>
    /// <item>Label ids (issue 26): the id with the most bilinear weight among the four neighbours, and none where the
    /// resampled mask sample is under half covered (<see cref="Id"/>); the majority rule over each k×k block then runs in
    /// the writer as without a lens. Never blended.</item>
    /// </list>
    /// Thread-safe: maps are built once per frame size and shared.
    /// </summary>
    public sealed class LensResampler
    {
        /// <summary>Four depth samples whose largest is within this fraction of their smallest are one smooth surface.</summary>
        public const float SmoothDepth = 0.02f;

        /// <summary>A step in 1/z across a cell this many times larger than both steps beside it is a discontinuity.</summary>
        public const float EvenStep = 2f;

        readonly Dictionary<int, LensSampleMap> _maps = new Dictionary<int, LensSampleMap>();

        /// <summary>One thread's output arrays, per pass, reused from view to view (see <see cref="Resample"/>'s reuse).</summary>
        sealed class Scratch
        {
            public ushort[] OverBlack = new ushort[0], OverWhite = new ushort[0];
            public float[] Linear = new float[0], Depth = new float[0], Normals = new float[0];
            public byte[] Mask = new byte[0];
            public ushort[] Ids = new ushort[0];
        }

        [ThreadStatic] static Scratch scratch;

        public LensResampler(LensDistortion lens, CameraIntrinsics output, LensPinholeCover wide)
        {
            Lens = lens ?? throw new ArgumentNullException(nameof(lens));
            Output = output ?? throw new ArgumentNullException(nameof(output));
            Wide = wide ?? throw new ArgumentNullException(nameof(wide));
        }

        public LensDistortion Lens { get; }
        public CameraIntrinsics Output { get; }
        public LensPinholeCover Wide { get; }

        /// <summary>The map for frames at supersampling <paramref name="k"/>, built on first use.</summary>
        public LensSampleMap Map(int k)
        {
            lock (_maps)
            {
                if (!_maps.TryGetValue(k, out var map)) _maps[k] = map = LensSampleMap.Build(Lens, Output, Wide, k);
                return map;
            }
        }

        /// <summary>
        /// The distorted frame of <paramref name="wide"/> (a wide render of <see cref="Wide"/>'s size × its supersampling):
        /// every pass it holds, resampled; the flags (gamma, normal frame) carried over. The mask comes out at 1 byte per
        /// sample, sRGB bytes as linear floats. With <paramref name="reuseThreadBuffers"/> the result's arrays are this
        /// thread's, per pass, and the next call on the thread overwrites them: for a caller that writes the frame out
        /// before resampling the next view (the capture's writer threads), which then makes no garbage per view — Unity's
        /// collector is not generational, and an 800×800 view at k = 2 with every pass is ~100 MB of arrays.
        /// </summary>
        public RawFrame Resample(RawFrame wide, bool reuseThreadBuffers = false)
        {
            if (wide == null) throw new ArgumentNullException(nameof(wide));
            var k = wide.Supersampling;
            var problems = wide.Validate();
            if (problems.Count == 0 && (wide.Width != Wide.Width * k || wide.Height != Wide.Height * k))
                problems.Add(new ValidationProblem("frame.Width", Text(wide.Width) + " × " + Text(wide.Height),
                    "is not the wide render the lens needs (" + Text(Wide.Width) + " × " + Text(Wide.Height) + " × supersampling " + Text(k) + ").",
                    "Render the view at LensCapture.WideRender's size and field of view."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());

            var map = Map(k);
            var n = map.Width * map.Height;
            var keep = reuseThreadBuffers ? scratch ?? (scratch = new Scratch()) : null;
            var result = new RawFrame(map.Width, map.Height, k)
            {
                ColorIsGammaEncoded = wide.ColorIsGammaEncoded,
                NormalsInUnityWorld = wide.NormalsInUnityWorld,
                NormalFloatsPerPixel = wide.NormalFloatsPerPixel,
                MaskBytesPerPixel = 1,
                ColorOverBlack = wide.ColorOverBlack == null ? null : Take(keep == null ? null : keep.OverBlack, n * 4, a => keep.OverBlack = a),
                ColorOverWhite = wide.ColorOverWhite == null ? null : Take(keep == null ? null : keep.OverWhite, n * 4, a => keep.OverWhite = a),
                ColorLinear = wide.ColorLinear != null || wide.ColorSrgb != null ? Take(keep == null ? null : keep.Linear, n * 4, a => keep.Linear = a) : null,
                Mask = wide.Mask == null ? null : Take(keep == null ? null : keep.Mask, n, a => keep.Mask = a),
                Depth = wide.Depth == null ? null : Take(keep == null ? null : keep.Depth, n, a => keep.Depth = a),
                Normals = wide.Normals == null ? null : Take(keep == null ? null : keep.Normals, n * wide.NormalFloatsPerPixel, a => keep.Normals = a),
                InstanceIds = wide.InstanceIds == null ? null : Take(keep == null ? null : keep.Ids, n, a => keep.Ids = a),
            };
            var halves = HalfFloat.Lookup;
            var decode = Srgb.DecodeLookup;
            int maskStride = wide.MaskBytesPerPixel, npp = wide.NormalFloatsPerPixel;
            for (var p = 0; p < n; p++)
            {
                if (!map.Locate(p, out var i00, out var dx, out var dy, out var ax, out var ay, out var nearest))
                {
                    Empty(result, p); // no ray: nothing there (reused arrays hold the last view's values)
                    continue;
                }
                int i10 = i00 + dx, i01 = i00 + dy, i11 = i00 + dx + dy;
                float w00 = (1 - ax) * (1 - ay), w10 = ax * (1 - ay), w01 = (1 - ax) * ay, w11 = ax * ay;
                if (result.ColorOverBlack != null)
                    for (var c = 0; c < 4; c++)
                    {
                        result.ColorOverBlack[p * 4 + c] = HalfFloat.FromFloat(Mix(halves, wide.ColorOverBlack, i00, i10, i01, i11, c, w00, w10, w01, w11));
                        result.ColorOverWhite[p * 4 + c] = HalfFloat.FromFloat(Mix(halves, wide.ColorOverWhite, i00, i10, i01, i11, c, w00, w10, w01, w11));
                    }
                if (wide.ColorLinear != null)
                    for (var c = 0; c < 4; c++)
                    {
                        var s = wide.ColorLinear;
                        result.ColorLinear[p * 4 + c] = s[i00 * 4 + c] * w00 + s[i10 * 4 + c] * w10 + s[i01 * 4 + c] * w01 + s[i11 * 4 + c] * w11;
                    }
                else if (wide.ColorSrgb != null)
                {
                    var s = wide.ColorSrgb;
                    for (var c = 0; c < 3; c++)
                        result.ColorLinear[p * 4 + c] = decode[s[i00 * 4 + c]] * w00 + decode[s[i10 * 4 + c]] * w10 + decode[s[i01 * 4 + c]] * w01 + decode[s[i11 * 4 + c]] * w11;
                    result.ColorLinear[p * 4 + 3] = (s[i00 * 4 + 3] * w00 + s[i10 * 4 + 3] * w10 + s[i01 * 4 + 3] * w01 + s[i11 * 4 + 3] * w11) / 255f;
                }
                if (wide.Mask != null)
                {
                    var m = wide.Mask;
                    var coverage = m[i00 * maskStride] * w00 + m[i10 * maskStride] * w10 + m[i01 * maskStride] * w01 + m[i11 * maskStride] * w11;
                    // Each sample is hit or not, as the mask pass renders it (no MSAA): the edge of the bilinear coverage,
                    // placed to a fraction of a wide sample; a pixel's coverage then comes from its k×k samples as without a
                    // lens, and the ids' majority rule agrees with it exactly (a pixel has an id where its mask reads ≥ 128).
                    result.Mask[p] = coverage >= 127.5f ? (byte)255 : (byte)0;
                }
                if (wide.Depth != null) result.Depth[p] = Depth(wide.Depth, map.WideWidth, map.WideHeight, i00, dx, dy, w00, w10, w01, w11, nearest);
                if (wide.Normals != null) Array.Copy(wide.Normals, nearest * npp, result.Normals, p * npp, npp);
                if (wide.InstanceIds != null)
                    result.InstanceIds[p] = Id(wide.InstanceIds, i00, i10, i01, i11, w00, w10, w01, w11, nearest, result.Mask == null ? -1 : result.Mask[p]);
            }
            return result;
        }

        /// <summary>
        /// The hook for integer channels that must never be blended (label ids): each output sample takes the nearest wide
        /// sample's <paramref name="channels"/> values. <paramref name="wide"/> is at the wide size × <paramref name="k"/>,
        /// <paramref name="output"/> at the output size × k, both bottom row first like every readback.
        /// </summary>
        public void ResampleNearest<T>(T[] wide, int channels, T[] output, int k)
        {
            var map = Map(k);
            var n = map.Width * map.Height;
            RawFrame.RequireOutput("output", output, (long)n * channels, "values (" + Text(channels) + " per sample)");
            if (wide == null || wide.Length != (long)map.WideWidth * map.WideHeight * channels)
                throw new InvalidParameterException(new[] { new ValidationProblem("wide", wide == null ? "null" : "length " + Text(wide.Length),
                    "is not a wide render of " + Text(map.WideWidth) + " × " + Text(map.WideHeight) + " × " + Text(channels) + " values.", "Pass the wide render's readback.") });
            for (var p = 0; p < n; p++)
            {
                if (!map.Locate(p, out _, out _, out _, out _, out _, out var nearest))
                {
                    for (var c = 0; c < channels; c++) output[p * channels + c] = default(T);
                    continue;
                }
                Array.Copy(wide, nearest * channels, output, p * channels, channels);
            }
        }

        /// <summary>A fresh array, or the thread's one of exactly that length (replaced only when the size changes).</summary>
        static T[] Take<T>(T[] reused, int length, Action<T[]> keep)
        {
            if (keep == null || reused == null) return new T[length];
            if (reused.Length == length) return reused;
            var array = new T[length];
            keep(array);
            return array;
        }

        static void Empty(RawFrame f, int p)
        {
            if (f.ColorOverBlack != null) for (var c = 0; c < 4; c++) { f.ColorOverBlack[p * 4 + c] = 0; f.ColorOverWhite[p * 4 + c] = 0x3C00; } // the clears: black, white
            if (f.ColorLinear != null) for (var c = 0; c < 4; c++) f.ColorLinear[p * 4 + c] = 0;
            if (f.Mask != null) f.Mask[p] = 0;
            if (f.Depth != null) f.Depth[p] = 0;
            if (f.Normals != null) for (var c = 0; c < f.NormalFloatsPerPixel; c++) f.Normals[p * f.NormalFloatsPerPixel + c] = 0;
            if (f.InstanceIds != null) f.InstanceIds[p] = 0;
        }

        /// <summary>
        /// A label id is never blended: the id carrying the most bilinear weight among the four neighbours (the smaller id
        /// on a tie, as the majority rule), and none where the resampled mask sample <paramref name="mask"/> is under half
        /// covered — so that after the lens a pixel still has an id exactly where its mask reads ≥ 128, the agreement the
        /// writer's majority rule keeps (Documentation~/labels.md). Without a mask (−1), the nearest sample's id.
        /// </summary>
        static ushort Id(ushort[] ids, int i00, int i10, int i01, int i11, float w00, float w10, float w01, float w11, int nearest, int mask)
        {
            if (mask < 0) return ids[nearest];
            if (mask < 128) return 0;
            ushort a = ids[i00], b = ids[i10], c = ids[i01], d = ids[i11];
            ushort best = 0;
            var bestWeight = 0f;
            void Consider(ushort id)
            {
                if (id == 0) return;
                var weight = (a == id ? w00 : 0) + (b == id ? w10 : 0) + (c == id ? w01 : 0) + (d == id ? w11 : 0);
                if (weight > bestWeight || (weight == bestWeight && id < best))
                {
                    best = id;
                    bestWeight = weight;
                }
            }
            Consider(a);
            Consider(b);
            Consider(c);
            Consider(d);
            // Covered but no neighbour carries an id (the wide render's mask and ids disagree there): the nearest sample's.
            return best != 0 ? best : ids[nearest];
        }

        static float Mix(float[] halves, ushort[] s, int i00, int i10, int i01, int i11, int c, float w00, float w10, float w01, float w11) =>
            halves[s[i00 * 4 + c]] * w00 + halves[s[i10 * 4 + c]] * w10 + halves[s[i01 * 4 + c]] * w01 + halves[s[i11 * 4 + c]] * w11;

        static float Depth(float[] z, int width, int height, int i00, int dx, int dy, float w00, float w10, float w01, float w11, int nearest)
        {
            float a = z[i00], b = z[i00 + dx], c = z[i00 + dy], d = z[i00 + dx + dy];
            var lo = Math.Min(Math.Min(a, b), Math.Min(c, d));
            var hi = Math.Max(Math.Max(a, b), Math.Max(c, d));
            if (!(lo > 0)) return z[nearest];
            if (hi > lo * (1 + SmoothDepth))
            {
                // Steeper than the fast path allows: interpolate only when all four edges of the cell change evenly.
                int x0 = i00 % width, y0 = i00 / width;
                if (dx == 0 || dy == 0 || x0 < 1 || y0 < 1 || x0 + 2 >= width || y0 + 2 >= height) return z[nearest];
                if (!Even(z, i00, 1) || !Even(z, i00 + width, 1) || !Even(z, i00, width) || !Even(z, i00 + 1, width)) return z[nearest];
            }
            // 1/z is affine in pinhole image coordinates on a plane: interpolating it is exact there.
            return 1f / (w00 / a + w10 / b + w01 / c + w11 / d);
        }

        /// <summary>Whether 1/z steps from sample i to i + s no more than <see cref="EvenStep"/>× as much as from i − s to i or from i + s to i + 2s.</summary>
        static bool Even(float[] z, int i, int s)
        {
            float before = z[i - s], p = z[i], q = z[i + s], after = z[i + 2 * s];
            if (!(before > 0) || !(after > 0)) return false;
            float mid = Math.Abs(1 / q - 1 / p), left = Math.Abs(1 / p - 1 / before), right = Math.Abs(1 / after - 1 / q);
            return mid <= EvenStep * Math.Max(left, right) + 1e-6f / p;
        }

        static string Text(long v) => v.ToString(CultureInfo.InvariantCulture);
    }
}
