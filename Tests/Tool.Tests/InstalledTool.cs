using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// The tool as a user installs it (README, "The headless tool"): <c>dotnet pack</c> of the tool's folder, then
    /// <c>dotnet tool install --tool-path</c> from that folder into a clean one, with a NuGet config that lists only
    /// the packed folder, so it needs no network. Built once per test run and shared; deleted at process exit.
    /// </summary>
    static class InstalledTool
    {
        static readonly Lazy<string> Command = new Lazy<string>(Install);

        /// <summary>The installed <c>nerf-dataset</c> command (the shim dotnet tool install writes).</summary>
        public static string Path => Command.Value;

        /// <summary>The .nupkg <c>dotnet pack</c> wrote (its name carries the version <c>dotnet tool update</c> compares).</summary>
        public static string PackedPackage
        {
            get
            {
                _ = Command.Value;
                return _packed;
            }
        }

        static string _packed;

        /// <summary>The repository root: the first ancestor of the test binary that holds package.json and ProjectSettings/.</summary>
        public static string RepositoryRoot
        {
            get
            {
                for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
                    if (File.Exists(System.IO.Path.Combine(dir.FullName, "package.json")) && Directory.Exists(System.IO.Path.Combine(dir.FullName, "ProjectSettings")))
                        return dir.FullName;
                throw new InvalidOperationException("Repository root not found above " + AppContext.BaseDirectory);
            }
        }

        static string Install()
        {
            var root = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "nerf-tool-install-" + Guid.NewGuid().ToString("N"));
            var feed = System.IO.Path.Combine(root, "feed");
            var tools = System.IO.Path.Combine(root, "tools");
            Directory.CreateDirectory(feed);
            AppDomain.CurrentDomain.ProcessExit += (s, e) => { try { Directory.Delete(root, true); } catch (IOException) { } catch (UnauthorizedAccessException) { } };

            var project = System.IO.Path.Combine(RepositoryRoot, "Assets", "NeRFDatasetCreator", "Tools~", "nerf-dataset");
            Dotnet("pack \"" + project + "\" -o \"" + feed + "\" --nologo", RepositoryRoot);
            _packed = Directory.GetFiles(feed, "*.nupkg").Single();
            var config = System.IO.Path.Combine(root, "nuget.config");
            File.WriteAllText(config,
                "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<configuration><packageSources><clear />" +
                "<add key=\"packed\" value=\"" + feed + "\" /></packageSources></configuration>\n");
            Dotnet("tool install --tool-path \"" + tools + "\" --configfile \"" + config + "\" NerfDatasetCreator.Tool", root);
            var command = System.IO.Path.Combine(tools, OperatingSystem.IsWindows() ? "nerf-dataset.exe" : "nerf-dataset");
            Assert.That(File.Exists(command), Is.True, "dotnet tool install wrote no " + command);
            return command;
        }

        static void Dotnet(string arguments, string workingDirectory)
        {
            var run = Run("dotnet", arguments, workingDirectory);
            if (run.ExitCode != 0) Assert.Fail("dotnet " + arguments + " failed:\n" + run);
        }

        /// <summary>Runs a program to the end, without the MSBuild variables the surrounding `dotnet test` sets.</summary>
        public static ProcessRun Run(string fileName, string arguments, string workingDirectory)
        {
            var start = new ProcessStartInfo(fileName, arguments)
            {
                WorkingDirectory = workingDirectory,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            foreach (var key in new System.Collections.Generic.List<string>(start.Environment.Keys))
                if (key.StartsWith("MSBuild", StringComparison.OrdinalIgnoreCase) || key == "MSBUILD_EXE_PATH") start.Environment.Remove(key);
            start.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
            start.Environment["DOTNET_NOLOGO"] = "1";
            var watch = Stopwatch.StartNew();
            using var process = Process.Start(start);
            var stderr = process.StandardError.ReadToEndAsync();
            var stdout = process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            return new ProcessRun { ExitCode = process.ExitCode, Out = stdout, Err = stderr.Result, Seconds = watch.Elapsed.TotalSeconds };
        }
    }

    sealed class ProcessRun
    {
        public int ExitCode;
        public string Out;
        public string Err;
        public double Seconds;

        public override string ToString() => "exit " + ExitCode + "\n--- stdout\n" + Out + "--- stderr\n" + Err;
    }
}
