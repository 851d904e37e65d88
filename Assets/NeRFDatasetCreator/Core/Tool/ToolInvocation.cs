using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>The parsed command line of the <c>nerf-dataset</c> tool: which command, its options, and the usage mistakes.</summary>
    public sealed class ToolInvocation
    {
        public const string HelpCommand = "help";

        /// <summary>The <see cref="Command"/> of <c>nerf-dataset --version</c>.</summary>
        public const string VersionCommand = "version";

        readonly Func<TextWriter, TextWriter, int> _run;

        internal ToolInvocation(string command, object options, List<string> errors, Func<TextWriter, TextWriter, int> run)
        {
            Command = command;
            Options = options;
            Errors = errors;
            _run = run;
        }

        /// <summary>The command's name as typed ("plan", "check" …), or "help", or "version".</summary>
        public string Command { get; }

        /// <summary>The command's own options (<see cref="PlanCommand.Options"/>, <see cref="EvaluationOptions"/> …); null for help or an unknown command.</summary>
        public object Options { get; }

        /// <summary>Usage mistakes; the command runs only when this is empty.</summary>
        public List<string> Errors { get; }

        /// <summary>Runs the command (help prints <see cref="ToolCommands.Usage"/>); only when <see cref="Errors"/> is empty.</summary>
        public int Run(TextWriter stdout, TextWriter stderr)
        {
            if (Errors.Count > 0 || _run == null) throw new InvalidOperationException("the command line has usage mistakes: " + string.Join(" ", Errors));
            return _run(stdout, stderr);
        }
    }
}
