using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset plan --config f --out d</c>: plans the views of a settings file (target at the origin,
    /// unknown bounds) and writes the dataset's JSON files, a rig preview PLY and its picture (top and side views), but no images.
    /// </summary>
    public static class PlanCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("plan", "plan --config <settings.json> --out <dir>",
            "the JSON files and a rig preview, no images", Parse, Run).WithOptions(
            "--config <settings.json>  the settings file (the window's Save, or a sample config)",
            "--out <dir>               the dataset folder to write (a new folder, or one the tool wrote; the config's outputFolder is ignored)");

        public sealed class Options
        {
            /// <summary><c>--config &lt;file&gt;</c>: the settings file.</summary>
            public string ConfigPath { get; set; }

            /// <summary><c>--out &lt;dir&gt;</c>: the dataset folder to create.</summary>
            public string OutputFolder { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("config", "out");
            if (arguments.Positionals.Count > 0) arguments.Error("plan takes no positional argument ('" + arguments.Positionals[0] + "').");
            return new Options
            {
                ConfigPath = arguments.RequiredPath("config", "plan needs --config <settings.json>."),
                OutputFolder = arguments.RequiredPath("out", "plan needs --out <dataset-folder>."),
            };
        }

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) => Run(options.ConfigPath, options.OutputFolder, stdout, stderr);

        public static int Run(string configPath, string outputFolder, TextWriter stdout, TextWriter stderr)
        {
            SettingsReadResult read;
            try
            {
                read = DatasetSettingsJson.ReadFile(configPath);
            }
            catch (SettingsFormatException e)
            {
                foreach (var error in e.All) stderr.WriteLine("error: " + error.Message);
                // Wrong values leave the rest readable: its range problems are printed now too, not in a second round.
                if (e.Partial != null)
                {
                    var wrong = new System.Collections.Generic.HashSet<string>(e.All.Select(x => x.Field), StringComparer.Ordinal);
                    foreach (var problem in CapturePlan.Check(e.Partial.Settings, HeadlessClip.Target(e.Partial.Settings)).Where(p => !wrong.Contains(p.Field)))
                        stderr.WriteLine("error: " + e.Partial.Placed(problem));
                }
                return ToolExitCodes.UsageError;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                stderr.WriteLine("error: cannot read the config " + configPath + ": " + e.Message);
                return ToolExitCodes.UsageError;
            }
            foreach (var warning in read.Warnings) stderr.WriteLine("warning: " + warning);

            // The config's outputFolder is where Unity's capture puts datasets; --out names this one, which is all plan
            // needs (its help says so). No warning: the bundled sample config has one, and the README plans it first.
            var settings = read.Settings;
            // A dynamic config ending at the clip's length is planned with an assumed clip, said in a note (HeadlessClip).
            var target = HeadlessClip.Target(settings);
            var problems = CapturePlan.Check(settings, target);
            if (problems.Count > 0)
            {
                foreach (var problem in problems) stderr.WriteLine("error: " + read.Placed(problem));
                return ToolExitCodes.UsageError;
            }
            if (HeadlessClip.Applies(settings)) stderr.WriteLine("note: " + HeadlessClip.Note(settings));
            var plan = CapturePlan.Build(settings, target);
            foreach (var warning in plan.Warnings) stderr.WriteLine("warning: " + warning);

            DatasetWriteSession session;
            try
            {
                session = DatasetWriteSession.Begin(outputFolder, settings.Overwrite, field: "--out", rendersImages: false);
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                return ToolExitCodes.UsageError;
            }
            foreach (var note in session.Recovered) stderr.WriteLine("note: " + note);
            foreach (var leftover in session.Leftovers)
                stderr.WriteLine("note: left over: " + leftover + (leftover.Removable ? " `nerf-dataset clean " + Path.GetDirectoryName(session.FinalFolder) + "` removes it." : ""));

            try
            {
                DatasetMetadataFiles.Write(session, plan, new Provenance(DateTime.UtcNow, null, "nerf-dataset plan", imagesRendered: false));
                session.WriteBytes(DatasetLayout.RigPreviewFileName, stream => RigPreviewPly.Write(plan, stream));
                File.WriteAllBytes(session.PathOf(RigPreviewPicture.FileName), RigPreviewPicture.Encode(plan));
                session.Commit();
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                stderr.WriteLine("error: " + e.Message);
                session.End();
                stderr.WriteLine("note: " + session.DescribeAbandoned());
                return ToolExitCodes.Failure;
            }

            stdout.WriteLine("planned " + plan.ViewsOf(DatasetSplit.Train).Count + " train, " + plan.ViewsOf(DatasetSplit.Val).Count + " val, " +
                             plan.ViewsOf(DatasetSplit.Test).Count + " test views at distance " + ValidationProblem.Format(plan.Distance) + " into " + session.FinalFolder);
            if (plan.Time != null) stdout.WriteLine(TimeSummary.Describe(plan.Time));
            stdout.WriteLine("wrote transforms_train.json, transforms_val.json, transforms_test.json, " + DatasetLayout.ConfigFileName + ", " + EvalProtocolFile.FileName + ", " +
                             DatasetLayout.RigPreviewFileName + ", " + RigPreviewPicture.FileName + " (no images: render them with the Unity plugin)");
            return ToolExitCodes.Success;
        }
    }
}
