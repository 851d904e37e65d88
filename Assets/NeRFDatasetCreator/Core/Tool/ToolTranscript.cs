using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One run of a <c>nerf-dataset</c> command line in this process, with what it printed: Unity's Dataset Tools run
    /// the tool's own argument parsing and commands (<see cref="ToolCommands"/>), so the lines a Unity user reads are
    /// the lines the tool prints, and <see cref="CommandLine"/> is the same run from a terminal. Safe to run on a
    /// worker thread (nothing here touches Unity).
    /// </summary>
    public sealed class ToolTranscript
    {
        ToolTranscript(IReadOnlyList<string> arguments, int exitCode, string output, string errors, string combined)
        {
            Arguments = arguments;
            ExitCode = exitCode;
            Output = output;
            Errors = errors;
            _combined = combined;
        }

        readonly string _combined;

        public IReadOnlyList<string> Arguments { get; }

        /// <summary>0 success, 1 problems found or refused or failed, 2 usage or config error (<see cref="ToolExitCodes"/>).</summary>
        public int ExitCode { get; }

        /// <summary>What the command printed on stdout ("\n" line ends).</summary>
        public string Output { get; }

        /// <summary>What it printed on stderr: errors, warnings and notes.</summary>
        public string Errors { get; }

        public bool Succeeded => ExitCode == ToolExitCodes.Success;

        /// <summary>The terminal command that does the same, e.g. <c>nerf-dataset convert "My Data/lego" --to colmap</c>.</summary>
        public string CommandLine => DescribeCommandLine(Arguments);

        /// <summary>Every line of stdout and stderr in the order the command printed them, without blank lines.</summary>
        public IReadOnlyList<string> Lines =>
            _combined.Split('\n').Select(l => l.TrimEnd('\r')).Where(l => l.Length > 0).ToList();

        /// <summary>Runs <paramref name="arguments"/> as <c>nerf-dataset</c> would.</summary>
        public static ToolTranscript Run(params string[] arguments)
        {
            if (arguments == null) throw new ArgumentNullException(nameof(arguments));
            var combined = new StringBuilder();
            var stdout = new TeeWriter(combined);
            var stderr = new TeeWriter(combined);
            var code = ToolCommands.Run(arguments, stdout, stderr);
            return new ToolTranscript(arguments.ToList(), code, stdout.ToString(), stderr.ToString(), combined.ToString());
        }

        /// <summary>The arguments as one shell line; arguments with spaces or quotes are double-quoted.</summary>
        public static string DescribeCommandLine(IEnumerable<string> arguments) =>
            "nerf-dataset " + string.Join(" ", arguments.Select(Quote));

        static string Quote(string argument)
        {
            if (argument.Length > 0 && argument.All(c => !char.IsWhiteSpace(c) && c != '"' && c != '\'' && c != '$' && c != '`')) return argument;
            return "\"" + argument.Replace("\"", "\\\"") + "\"";
        }

        /// <summary>A writer that also appends to a log shared by stdout and stderr, so the order of their lines is kept.</summary>
        sealed class TeeWriter : StringWriter
        {
            readonly StringBuilder _both;

            public TeeWriter(StringBuilder both)
                : base(System.Globalization.CultureInfo.InvariantCulture)
            {
                _both = both;
                NewLine = "\n";
            }

            public override void Write(char value)
            {
                base.Write(value);
                _both.Append(value);
            }

            public override void Write(string value)
            {
                base.Write(value);
                _both.Append(value);
            }

            public override void Write(char[] buffer, int index, int count)
            {
                base.Write(buffer, index, count);
                _both.Append(buffer, index, count);
            }
        }
    }
}
