using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One row of the command table (<see cref="ToolCommands.All"/>): a command's name, its line in <c>--help</c>,
    /// the options it takes without a value, and how it reads its arguments into its options and runs them. Each
    /// command's own file makes its row with <see cref="Of{TOptions}"/>; the parser, the help text and the dispatcher
    /// read only the table.
    /// </summary>
    public sealed class ToolCommand
    {
        /// <summary>The column at which the help text's descriptions start, where the synopsis leaves room.</summary>
        const int SummaryColumn = 58;

        readonly Func<ToolArguments, ToolInvocation> _parse;

        ToolCommand(string name, string synopsis, string summary, IReadOnlyList<string> flags, Func<ToolArguments, ToolInvocation> parse,
            IReadOnlyList<string> options = null)
        {
            Name = name;
            Synopsis = synopsis;
            Summary = summary;
            Flags = flags;
            _parse = parse;
            Options = options ?? Array.Empty<string>();
        }

        /// <param name="name">What the user types first, e.g. "check".</param>
        /// <param name="synopsis">The command with its arguments as <c>--help</c> shows them, e.g. <c>check &lt;dir&gt; [--split S]</c>.</param>
        /// <param name="summary">What it does, in a few words after the synopsis.</param>
        /// <param name="parse">Reads the arguments into the command's options, adding every usage mistake to <see cref="ToolArguments.Errors"/>.</param>
        /// <param name="run">Runs the options: prints to stdout and stderr, returns a <see cref="ToolExitCodes"/> code.</param>
        /// <param name="flags">Its options that take no value (<c>--depths</c>): the next argument is never read as their value.</param>
        public static ToolCommand Of<TOptions>(string name, string synopsis, string summary, Func<ToolArguments, TOptions> parse,
            Func<TOptions, TextWriter, TextWriter, int> run, params string[] flags) where TOptions : class =>
            new ToolCommand(name, synopsis, summary, flags, arguments =>
            {
                var options = parse(arguments);
                return new ToolInvocation(name, options, arguments.Errors, (stdout, stderr) => run(options, stdout, stderr));
            });

        public string Name { get; }
        public string Synopsis { get; }
        public string Summary { get; }
        public IReadOnlyList<string> Flags { get; }

        /// <summary>One line per option for <c>nerf-dataset &lt;command&gt; --help</c> ("--split S  only that split …"); may be empty.</summary>
        public IReadOnlyList<string> Options { get; }

        /// <summary>This command with its option lines for <see cref="Usage"/>; each line is "--option  what it does".</summary>
        public ToolCommand WithOptions(params string[] lines) => new ToolCommand(Name, Synopsis, Summary, Flags, _parse, lines);

        /// <summary>
        /// What <c>nerf-dataset &lt;command&gt; --help</c> prints, and what a usage mistake in this command prints
        /// after its errors: only this command's synopsis, summary and options, not the whole table.
        /// </summary>
        public string Usage
        {
            get
            {
                var text = "usage: nerf-dataset " + Synopsis + "\n" + Summary + "\n";
                if (Options.Count > 0) text += "options:\n" + string.Concat(Options.Select(o => "  " + o + "\n"));
                return text + ToolCommands.ExitCodes;
            }
        }

        /// <summary>The command's line in <c>--help</c>: the synopsis, then the summary from column 58 or two spaces after it.</summary>
        public string HelpLine
        {
            get
            {
                var line = "  " + Synopsis + "  ";
                return line.PadRight(SummaryColumn) + Summary;
            }
        }

        internal ToolInvocation Parse(ToolArguments arguments) => _parse(arguments);
    }
}
