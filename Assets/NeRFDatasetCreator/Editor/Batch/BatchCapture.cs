using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The batch-mode entry point:
    /// <c>Unity -batchmode -projectPath P -executeMethod NerfDatasetCreator.Editor.BatchCapture.Run -nerfConfig F
    /// [-nerfScene S] [-nerfOut D] [-nerfShard i/N] -logFile -</c>. Exits 0 on success, 1 when the capture failed or its
    /// preflight or self-check found problems,
    /// 2 when the arguments, config, scene or target are invalid (every problem printed), 3 without a graphics device.
    /// The capture runs to the end inside <see cref="Run"/>, which then exits Unity with its code: -quit is not needed.
    /// </summary>
    public static class BatchCapture
    {
        public const int Success = 0, Failure = 1, InvalidInput = 2, NoGraphicsDevice = 3;

        const string Prefix = "[NeRF Dataset Creator] ";

        public static void Run()
        {
            int code;
            try
            {
                code = Execute(Environment.GetCommandLineArgs());
            }
            catch (Exception e)
            {
                Debug.LogException(e);
                code = Failure;
            }
            // Only a batch run may close the editor; called from a script in a GUI session, it just returns.
            if (Application.isBatchMode) EditorApplication.Exit(code);
        }

        /// <summary>Runs a capture from command-line arguments and returns the exit code (also for tests and scripts).</summary>
        public static int Execute(IReadOnlyList<string> argv)
        {
            var args = BatchArguments.Parse(argv);
            if (!args.IsValid) return Refuse("the command line is invalid", args.Problems);
            if (CaptureEnvironment.HasNoGraphicsDevice)
            {
                Debug.LogError(Prefix + "Unity was started with -nographics, so it has no graphics device and cannot render. " +
                    "Run without -nographics; on a machine without a display keep -batchmode and start Unity under xvfb-run.");
                return NoGraphicsDevice;
            }

            var projectRoot = Directory.GetParent(Application.dataPath).FullName;
            var configPath = Path.GetFullPath(Path.Combine(projectRoot, args.ConfigPath));
            // A folder is not "missing": DatasetSettingsJson.ReadFile says it is a folder and names a config inside it.
            if (!File.Exists(configPath) && !Directory.Exists(configPath))
                return Refuse("the config file is missing", new[] { new ValidationProblem("-nerfConfig", configPath, "does not exist.", "Pass the path of a config saved by the window (Save config for batch…) or written by hand.") });
            SettingsReadResult read;
            try
            {
                read = DatasetSettingsJson.ReadFile(configPath);
            }
            catch (SettingsFormatException e)
            {
                Debug.LogError(Prefix + e.Message);
                return InvalidInput;
            }
            foreach (var warning in read.Warnings) Debug.LogWarning(Prefix + warning);
            var settings = read.Settings;

            // -nerfScene is project-relative; the config's "scene" may also be relative to the config file (ScenePath),
            // so the sample's configs work where Package Manager imports them.
            var scenePath = string.IsNullOrWhiteSpace(args.Scene) ? ScenePath.Resolve(settings.Scene, configPath, projectRoot) : args.Scene;
            if (scenePath == null)
                return Refuse("the scene is outside the project", new[] { new ValidationProblem("scene", settings.Scene, "leads outside the project folder " + projectRoot + ".", "Name a scene of this project: Assets/… from the project folder, or a path relative to the config file.") });
            if (!string.IsNullOrWhiteSpace(scenePath))
            {
                if (!File.Exists(Path.Combine(projectRoot, scenePath)))
                    return Refuse("the scene is missing", new[] { new ValidationProblem("-nerfScene", scenePath, "is not a scene file of this project.", "Give the scene's path from the project folder, e.g. Assets/Scenes/Lego.unity.") });
                EditorSceneManager.OpenScene(scenePath, OpenSceneMode.Single);
            }
            var target = SceneObjects.Find(settings.Target);
            if (target == null)
                return Refuse("the target is missing", new[] { new ValidationProblem("target", settings.Target ?? "", "names no object in the open scene.", "Set \"target\" in the config to the object's hierarchy path or name.") });

            var shard = args.Shard ?? ShardSpec.Whole;
            var prepared = DatasetCapture.Prepare(settings, target, projectRoot, shard, args.OutputFolder);
            if (!prepared.IsValid) return Refuse("the settings cannot be captured", prepared.Problems);
            foreach (var warning in prepared.Warnings) Debug.LogWarning(Prefix + warning);

            Debug.Log(Prefix + "capturing " + prepared.ViewCount + " views of '" + target.name + "'" +
                (shard.Count > 1 ? " (shard " + shard.Index + "/" + shard.Count + ")" : "") + " into " + prepared.DatasetFolder);
            var result = DatasetCapture.RunBlocking(prepared, new LogProgress(), "unity-batch");
            // A written dataset whose self-check failed (check_report.json in it) is a failure too: its files would train a worse model.
            if (result.Succeeded && !result.CheckFailed) Debug.Log(result.Message);
            else Debug.LogError(result.Message);
            return result.Succeeded && !result.CheckFailed ? Success : Failure;
        }

        static int Refuse(string what, IEnumerable<ValidationProblem> problems)
        {
            Debug.LogError(Prefix + "nothing was captured: " + what + ".\n" + string.Join("\n", problems.Select(p => "  " + p)));
            return InvalidInput;
        }

        /// <summary>Progress lines in the log, at most every two seconds, and never a cancel.</summary>
        sealed class LogProgress : ICaptureProgress
        {
            double _lastReport = double.NegativeInfinity;

            public bool CancelRequested => false;

            public void Report(ThroughputMeter meter)
            {
                if (meter.Done < meter.Total && meter.ElapsedSeconds - _lastReport < 2) return;
                _lastReport = meter.ElapsedSeconds;
                Debug.Log(Prefix + meter.Describe());
            }

            public void Close()
            {
            }
        }
    }
}
