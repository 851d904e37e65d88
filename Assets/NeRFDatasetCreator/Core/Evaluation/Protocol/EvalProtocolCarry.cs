using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// convert keeps the dataset's <c>eval_protocol.json</c>: an export written outside the dataset's root (ngp/,
    /// colmap/, dynamic3dgs/, gaussian_grouping/, or --out) gets a copy, so the protocol travels with the data a trainer
    /// is given. Never overwritten: an identical copy already there is left, a different one is left with a warning.
    /// </summary>
    public static class EvalProtocolCarry
    {
        public static void Copy(string datasetRoot, string output, StagedOutput staged, List<ValidationProblem> warnings)
        {
            var source = Path.Combine(datasetRoot, EvalProtocolFile.FileName);
            var destination = Path.Combine(output, EvalProtocolFile.FileName);
            if (!File.Exists(source) || string.Equals(Path.GetFullPath(source), Path.GetFullPath(destination), System.StringComparison.Ordinal)) return;
            if (File.Exists(destination))
            {
                if (FileOps.ReadText(destination) != FileOps.ReadText(source))
                    warnings?.Add(new ValidationProblem(destination, "(differs)", "is not the dataset's " + EvalProtocolFile.FileName + " and was left as it is.",
                        "Delete it and convert again to carry the dataset's protocol."));
                return;
            }
            staged.Copy(source, destination);
        }
    }
}
