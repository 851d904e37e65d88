using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The dataset's records agree with each other (Documentation~/check.md, "records"): dataset_config.json's
    /// <c>unity_frame.output_to_unity</c> is the inverse of its <c>scene_normalisation</c> with the axes swapped back
    /// (place-splat trusts the first, every converter the second); each transforms file's <c>scene_normalisation</c> is
    /// the config's; and <c>eval_protocol.json</c>'s background is the one the recorded settings give
    /// (<see cref="EvalProtocolFile.Derived"/>), so evaluate scores over what the capture meant. A hand-edit of one record
    /// and not the other is what this catches.
    /// </summary>
    public static class RecordsCheck
    {
        public const string CheckName = "records";

        /// <summary>Largest entry difference of two matrices that are the same record written twice at round-trip precision.</summary>
        public const double MatrixTolerance = 1e-9;

        public static DatasetCheckResult Run(string root, DatasetConfigFile config, ICollection<DatasetProblem> problems)
        {
            var json = config?.Config?.Json;
            if (json == null) return DatasetCheckResult.Skip(CheckName, "no readable " + DatasetLayout.ConfigFileName);
            var compared = new List<string>();
            var failed = 0;
            void Fail(string file, string message)
            {
                failed++;
                problems.Add(new DatasetProblem(CheckName, file, -1, message));
            }

            SceneNormalisation normalisation = null;
            if (json[BlenderTransformsWriter.SceneNormalisationKey] is JObject n)
            {
                try { normalisation = SceneNormalisation.FromJson(n); }
                catch (InvalidParameterException e) { Fail(DatasetLayout.ConfigFileName, e.Message); }
            }
            if (normalisation != null && json[UnityFrameRecord.Key] is JObject)
            {
                compared.Add("unity_frame");
                try
                {
                    var recorded = UnityFrameRecord.Read(json).OutputToUnity;
                    var expected = UnityFrameRecord.Matrix(normalisation);
                    var d = MaxDifference(recorded, expected);
                    if (d > MatrixTolerance * Math.Max(1, MaxAbs(expected)))
                        Fail(DatasetLayout.ConfigFileName, "unity_frame.output_to_unity differs from the inverse of scene_normalisation by up to " + DatasetCheckResult.Number(d, "0.###e0") +
                            ": one record was edited without the other, so place-splat and the converters would put the target in different places. Capture again, or remove unity_frame (scene_normalisation then gives it).");
                }
                catch (InvalidParameterException e) { Fail(DatasetLayout.ConfigFileName, e.Message); }
            }
            if (normalisation != null)
                foreach (var split in DatasetSplits.Names)
                {
                    var path = DatasetFolder.SplitPath(root, split);
                    if (!File.Exists(path)) continue;
                    JObject top;
                    try { top = JObject.Parse(File.ReadAllText(path)); }
                    catch (Exception e) when (e is IOException || e is Newtonsoft.Json.JsonException || e is UnauthorizedAccessException) { continue; } // the reader reports it
                    if (!(top[BlenderTransformsWriter.SceneNormalisationKey] is JObject own)) continue;
                    compared.Add(Path.GetFileName(path));
                    SceneNormalisation theirs;
                    try { theirs = SceneNormalisation.FromJson(own); }
                    catch (InvalidParameterException e) { Fail(Path.GetFileName(path), e.Message); continue; }
                    var d = Math.Max(Math.Abs(theirs.Scale - normalisation.Scale), (theirs.Centre - normalisation.Centre).Length);
                    if (d > MatrixTolerance * Math.Max(1, Math.Max(normalisation.Scale, normalisation.Centre.Length)))
                        Fail(Path.GetFileName(path), "scene_normalisation (" + theirs + ") is not dataset_config.json's (" + normalisation + "): the split was written by another capture or edited. Capture again, or restore the file.");
                }

            if (File.Exists(Path.Combine(root, EvalProtocolFile.FileName)))
            {
                compared.Add(EvalProtocolFile.FileName);
                try
                {
                    var written = EvalProtocolFile.Read(root);
                    var derived = EvalProtocolFile.Derived(root);
                    if (written.Background != derived.Background || written.ColourText != derived.ColourText)
                        Fail(EvalProtocolFile.FileName, "background is " + written.Background + " (" + written.ColourText + "), but the settings recorded in dataset_config.json give " +
                                                        derived.Background + " (" + derived.ColourText + "): evaluate would score over another colour than the capture meant. Write the capture's choice into settings." + EvalProtocol.SettingsKey + " and capture again, or correct eval_protocol.json.");
                }
                catch (InvalidParameterException e) { Fail(EvalProtocolFile.FileName, e.Message); }
            }

            if (compared.Count == 0) return DatasetCheckResult.Skip(CheckName, "the dataset records neither unity_frame, scene_normalisation in its transforms files nor eval_protocol.json");
            return new DatasetCheckResult(CheckName, failed > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                failed + " of " + compared.Count + " records disagree (" + string.Join(", ", compared) + ")",
                "every record states the same frame and background (matrices within " + DatasetCheckResult.Number(MatrixTolerance, "0e0") + " relative)", null);
        }

        static double MaxDifference(Matrix4x4d a, Matrix4x4d b)
        {
            var d = 0.0;
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++) d = Math.Max(d, Math.Abs(a[r, c] - b[r, c]));
            return d;
        }

        static double MaxAbs(Matrix4x4d a)
        {
            var d = 0.0;
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++) d = Math.Max(d, Math.Abs(a[r, c]));
            return d;
        }
    }
}
