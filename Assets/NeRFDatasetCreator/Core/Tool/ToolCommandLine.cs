using System;
using System.Collections.Generic;

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
            if (command == "-h" || command == "--help" || command == ToolInvocation.HelpCommand) return Help(errors);
            var positionals = new List<string>();
            var options = new Dictionary<string, string>(StringComparer.Ordinal);
            for (var i = 1; i < args.Count; i++)
            {
                var arg = args[i];
                if (arg == "-h" || arg == "--help") return Help(errors);
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

            var entry = ToolCommands.Find(command);
            if (entry == null)
            {
                errors.Add("unknown command '" + command + "'.");
                return new ToolInvocation(command, null, errors, null);
            }
            return entry.Parse(new ToolArguments(command, options, positionals, errors));
        }

        static ToolInvocation Help(List<string> errors) =>
            new ToolInvocation(ToolInvocation.HelpCommand, null, errors, (stdout, stderr) =>
            {
                stdout.WriteLine(ToolCommands.Usage);
                return ToolExitCodes.Success;
            });
    }
}
