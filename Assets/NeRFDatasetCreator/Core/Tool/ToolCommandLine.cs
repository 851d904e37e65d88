using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Parses <c>nerf-dataset</c>'s arguments. Options take their value as the next argument or after '='
    /// (<c>--out=dir</c>); option names are case-sensitive like most .NET and POSIX tools. The command named first
    /// is looked up in <see cref="ToolCommands.All"/>, which reads its own options.
    /// </summary>
    public static class ToolCommandLine
    {
        public static ToolInvocation Parse(IReadOnlyList<string> args)
        {
            var errors = new List<string>();
            if (args == null || args.Count == 0)
            {
                errors.Add("no command given.");
                return Help(errors);
            }
            var command = args[0];
            if (command == "--version") return Version(args, errors);
            if (IsHelp(command) || command == ToolInvocation.HelpCommand)
            {
                // "help check" is "check --help".
                if (command == ToolInvocation.HelpCommand && args.Count == 2 && ToolCommands.Find(args[1]) != null) return Help(errors, ToolCommands.Find(args[1]));
                return Help(errors);
            }
            var entry = ToolCommands.Find(command);
            var positionals = new List<string>();
            var options = new Dictionary<string, string>(StringComparer.Ordinal);
            for (var i = 1; i < args.Count; i++)
            {
                var arg = args[i];
                if (IsHelp(arg)) return Help(errors, entry);
                if (arg.StartsWith("--", StringComparison.Ordinal))
                {
                    string name, value;
                    var eq = arg.IndexOf('=');
                    if (eq > 0)
                    {
                        name = arg.Substring(2, eq - 2);
                        value = arg.Substring(eq + 1);
                    }
                    else if (ToolCommands.IsFlag(arg.Substring(2)))
                    {
                        name = arg.Substring(2);
                        value = "true";
                    }
                    else
                    {
                        name = arg.Substring(2);
                        if (i + 1 >= args.Count || args[i + 1].StartsWith("--", StringComparison.Ordinal))
                        {
                            errors.Add("--" + name + " needs a value.");
                            continue;
                        }
                        value = args[++i];
                    }
                    if (options.ContainsKey(name)) errors.Add("--" + name + " is given twice.");
                    options[name] = value;
                }
                else positionals.Add(arg);
            }

            if (entry == null)
            {
                errors.Add("unknown command '" + command + "'." + SpellingSuggestion.Sentence(command, ToolCommands.All.Select(c => c.Name)));
                return new ToolInvocation(command, null, errors, null);
            }
            return entry.Parse(new ToolArguments(command, options, positionals, errors));
        }

        static bool IsHelp(string arg) => arg == "-h" || arg == "--help";

        /// <summary>The help of <paramref name="command"/> (its usage and options), or the whole table when null.</summary>
        static ToolInvocation Help(List<string> errors, ToolCommand command = null) =>
            new ToolInvocation(ToolInvocation.HelpCommand, null, errors, (stdout, stderr) =>
            {
                stdout.WriteLine(command?.Usage ?? ToolCommands.Usage);
                return ToolExitCodes.Success;
            });

        /// <summary><c>nerf-dataset --version</c>: one line, exit 0; anything after it is a mistake.</summary>
        static ToolInvocation Version(IReadOnlyList<string> args, List<string> errors)
        {
            if (args.Count > 1) errors.Add("--version takes nothing after it ('" + args[1] + "').");
            return new ToolInvocation(ToolInvocation.VersionCommand, null, errors, (stdout, stderr) =>
            {
                stdout.WriteLine(ToolCommands.VersionLine);
                return ToolExitCodes.Success;
            });
        }
    }
}
