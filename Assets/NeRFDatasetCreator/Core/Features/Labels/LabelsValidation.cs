using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <see cref="DatasetValidator"/>'s part for datasets whose frames name id maps: <c>labels.json</c> must be there
    /// and readable, since the maps' values mean nothing without it. (Whether the maps' pixels agree with the mask and
    /// across views is <c>nerf-dataset check</c>'s job: <see cref="InstanceMaskCheck"/>, <see cref="InstanceReprojectionCheck"/>.)
    /// </summary>
    public static class LabelsValidation
    {
        public static void Check(string folder, DatasetValidationReport report)
        {
            var path = Path.Combine(folder, DatasetLayout.LabelsFileName);
            if (!File.Exists(path))
            {
                report.Problems.Add(DatasetProblem.Structure(DatasetLayout.LabelsFileName, -1, null,
                    "is missing, but frames name instance/semantic maps (" + LabelFrameKeys.Instance + ", " + LabelFrameKeys.Semantic +
                    "); their ids mean nothing without it (recapture, or restore labels.json from the capture's folder)."));
                return;
            }
            try
            {
                LabelsJson.ReadFile(path);
            }
            catch (InvalidParameterException e)
            {
                foreach (var p in e.Problems)
                    report.Problems.Add(DatasetProblem.Structure(DatasetLayout.LabelsFileName, -1, null, p.Field.Replace(path, "").TrimStart(':', ' ') + " " + p.Value + " " + p.Reason + " (" + p.Fix + ")"));
            }
        }
    }
}
