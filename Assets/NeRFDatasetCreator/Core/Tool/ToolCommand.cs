using System;
using System.Collections.Generic;
using System.IO;

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

        ToolCommand(string name, string synopsis, string summary, IReadOnlyList<string> flags, Func<ToolArguments, ToolInvocation> parse)
        {
            Name = name;
            Synopsis = synopsis;
            Summary = summary;
            Flags = flags;
            _parse = parse;
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
