using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The self-check's report inside a dataset (<see cref="DatasetCheck.ReportFileName"/>), as the Unity layer writes it
    /// after a capture: one Core entry point, so the way it is written (atomically, never half a file, issue 32 item 4)
    /// is decided here and not in the Editor. A cancelled check writes nothing: its report covers only the views seen.
    /// </summary>
    public static class CheckReportFile
    {
        /// <summary>Writes <paramref name="report"/> into <paramref name="datasetFolder"/>; false (nothing written) for a cancelled report or a missing folder.</summary>
        public static bool WriteInto(string datasetFolder, DatasetCheckReport report)
        {
            if (report == null || report.Cancelled || string.IsNullOrEmpty(datasetFolder) || !Directory.Exists(datasetFolder)) return false;
            // Atomic: a kill or a domain reload mid-write leaves the old report or the new one, never half a file.
            AtomicFile.ReplaceText(Path.Combine(datasetFolder, DatasetCheck.ReportFileName), report.ToJson());
            return true;
        }
    }
}
