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
        public static bool TryRead(JToken token, out Matrix4x4d matrix)
        {
            matrix = Matrix4x4d.Identity;
            if (!(token is JArray rows) || rows.Count != 4) return false;
            var values = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (!(rows[r] is JArray row) || row.Count != 4) return false;
                for (var c = 0; c < 4; c++)
                    if (!JsonValues.TryNumber(row[c], out values[r * 4 + c])) return false;
            }
            matrix = Matrix4x4d.FromRowMajor(values);
            return true;
        }
    }
}
