using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>A 4×4 matrix as the transforms files write it: a list of 4 rows of 4 numbers (row-major).</summary>
    public static class JsonMatrix
    {
        /// <summary>
        /// The matrix when <paramref name="token"/> is 4 rows of 4 JSON numbers, as written (NaN and infinities kept, as
        /// Python's json writes them, so a check can report them); false for anything else.
        /// </summary>
        public static bool TryRead(JToken token, out Matrix4x4d matrix) => TryRead(token, null, out matrix, out _);

        /// <summary>
        /// As <see cref="TryRead(JToken, out Matrix4x4d)"/>, and when it fails, <paramref name="problem"/> says where, naming
        /// the key <paramref name="key"/> ("transform_matrix row 2 is not a list of 4 numbers.").
        /// </summary>
        public static bool TryRead(JToken token, string key, out Matrix4x4d matrix, out string problem)
        {
            matrix = Matrix4x4d.Identity;
            problem = null;
            if (!(token is JArray rows) || rows.Count != 4)
            {
                problem = key + " is not a list of 4 rows.";
                return false;
            }
            var values = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (!(rows[r] is JArray row) || row.Count != 4)
                {
                    problem = key + " row " + r + " is not a list of 4 numbers.";
                    return false;
                }
                for (var c = 0; c < 4; c++)
                    if (!JsonValues.TryNumber(row[c], out values[r * 4 + c]))
                    {
                        problem = key + "[" + r + "][" + c + "] is not a number (" + row[c].ToString(Formatting.None) + ").";
                        return false;
                    }
            }
            matrix = Matrix4x4d.FromRowMajor(values);
            return true;
        }
    }
}
