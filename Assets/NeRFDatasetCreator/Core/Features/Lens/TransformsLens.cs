using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The lens of a transforms file, under the keys nerfstudio and instant-ngp read: <c>k1 k2 k3 k4 p1 p2</c> at the
    /// top or per frame (a frame's key wins, as in both loaders), the model from nerfstudio's <c>camera_model</c>
    /// (<c>OPENCV</c>, <c>OPENCV_FISHEYE</c>; <c>PINHOLE</c>/<c>SIMPLE_PINHOLE</c> mean no distortion) or instant-ngp's
    /// <c>is_fisheye</c>, and OpenCV when only coefficients are given (instant-ngp's default). One lens per dataset:
    /// frames with different lenses are refused, since every export writes one shared camera.
    /// </summary>
    public static class TransformsLens
    {
        public static readonly string[] CoefficientKeys = { "k1", "k2", "k3", "k4", "p1", "p2" };

        /// <summary>
        /// The one lens of a transforms file, read frame by frame as <see cref="DatasetFolder"/> streams it: <see cref="Add"/>
        /// each frame, then <see cref="Finish"/>. The lens is null for a pinhole. Problems (an unknown model, a coefficient
        /// that is not a number or not the model's, frames that disagree) go to <see cref="Problems"/>, one report per file.
        /// </summary>
        public sealed class OfFile
        {
            readonly string _fileName;
            LensDistortion _first;
            int _objects;
            bool _done;

            public OfFile(string fileName) { _fileName = fileName; }

            public List<ValidationProblem> Problems { get; } = new List<ValidationProblem>();

            /// <summary>Reads one entry of <c>frames</c> (entries that are not objects are not counted, as before).</summary>
            public void Add(JObject top, JObject frame)
            {
                if (_done || frame == null) return;
                var i = _objects++;
                var count = Problems.Count;
                var lens = Lens(top, frame, _fileName + ": frames[" + i + "]", Problems);
                if (Problems.Count > count) { _done = true; _first = null; return; } // one report per file is enough
                if (i == 0) { _first = lens; return; }
                if (!Same(_first, lens))
                {
                    Problems.Add(new ValidationProblem(_fileName + ": frames[" + i + "]", Describe(lens),
                        "has another lens than frames[0] (" + Describe(_first) + "); convert writes one shared camera for the whole dataset.",
                        "Give every frame the same camera_model and k1…k4, p1, p2 (or undistort the images to one pinhole first)."));
                    _done = true;
                    _first = null;
                }
            }

            /// <summary>The file's lens: its frames' one lens, or the top-level keys' when it has no frame.</summary>
            public LensDistortion Finish(JObject top) => _objects == 0 && !_done ? Lens(top, null, _fileName, Problems) : _first;
        }

        /// <summary>The coefficient keys a frame (or, failing it, its file) gives a non-zero number, in <see cref="CoefficientKeys"/> order.</summary>
        public static IReadOnlyList<string> NonZeroCoefficients(JObject top, JObject frame)
        {
            List<string> keys = null;
            foreach (var key in CoefficientKeys)
            {
                var t = frame?[key] ?? top?[key];
                if (t != null && (t.Type == JTokenType.Float || t.Type == JTokenType.Integer) && (double)t != 0)
                    (keys = keys ?? new List<string>()).Add(key);
            }
            return keys ?? (IReadOnlyList<string>)System.Array.Empty<string>();
        }

        /// <summary>Whether two lenses (null = pinhole) are the same model with the same coefficients, bit for bit.</summary>
        public static bool Same(LensDistortion a, LensDistortion b)
        {
            if (a == null || b == null) return a == null && b == null;
            return a.Model == b.Model && a.K1.Equals(b.K1) && a.K2.Equals(b.K2) && a.K3.Equals(b.K3) && a.K4.Equals(b.K4)
                && a.P1.Equals(b.P1) && a.P2.Equals(b.P2);
        }

        public static string Describe(LensDistortion lens) => lens == null ? "PINHOLE" : lens.Describe();

        static LensDistortion Lens(JObject root, JObject frame, string field, ICollection<ValidationProblem> problems)
        {
            JToken Get(string key) => frame?[key] ?? root[key];
            var modelToken = Get("camera_model");
            string model = null;
            if (modelToken != null)
            {
                model = modelToken.Type == JTokenType.String ? ((string)modelToken).Trim().ToUpperInvariant() : null;
                if (model != "OPENCV" && model != "OPENCV_FISHEYE" && model != "PINHOLE" && model != "SIMPLE_PINHOLE")
                {
                    problems.Add(new ValidationProblem(field + ".camera_model", modelToken.ToString(Formatting.None),
                        "is not a camera model convert can carry (PINHOLE, SIMPLE_PINHOLE, OPENCV, OPENCV_FISHEYE).",
                        "Undistort the images to a pinhole first (e.g. ns-process-data or colmap image_undistorter), or fix the name."));
                    return null;
                }
            }
            var fisheyeToken = Get("is_fisheye");
            var isFisheye = fisheyeToken != null && fisheyeToken.Type == JTokenType.Boolean && (bool)fisheyeToken;
            var values = new double[CoefficientKeys.Length];
            var any = false;
            for (var k = 0; k < CoefficientKeys.Length; k++)
            {
                var token = Get(CoefficientKeys[k]);
                if (token == null || token.Type == JTokenType.Null) continue;
                if (!JsonValues.TryNumber(token, out values[k]))
                {
                    problems.Add(new ValidationProblem(field + "." + CoefficientKeys[k], token.ToString(Formatting.None), "must be a number (a lens distortion coefficient).", "Write the coefficient as a number, or remove it."));
                    return null;
                }
                any |= values[k] != 0;
            }
            if (model == "PINHOLE" || model == "SIMPLE_PINHOLE")
            {
                if (!any) return null;
                problems.Add(new ValidationProblem(field + ".camera_model", model,
                    "says the images are undistorted, but the file gives distortion coefficients (" + string.Join(", ", CoefficientKeys.Where((key, k) => values[k] != 0)) + ").",
                    "Set camera_model to OPENCV or OPENCV_FISHEYE if the images are distorted, or remove the coefficients."));
                return null;
            }
            var fisheye = model == "OPENCV_FISHEYE" || (model == null && isFisheye);
            if (!fisheye && !any) return null; // OPENCV with all-zero coefficients is a pinhole
            try
            {
                return new LensDistortion(fisheye ? LensModel.OpenCvFisheye : LensModel.OpenCv, values[0], values[1], values[2], values[3], values[4], values[5]);
            }
            catch (InvalidParameterException e)
            {
                foreach (var p in e.Problems) problems.Add(new ValidationProblem(field + "." + p.Field, p.Value, p.Reason, p.Fix));
                return null;
            }
        }
    }
}
