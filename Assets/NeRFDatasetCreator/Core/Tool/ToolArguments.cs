using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One command's arguments as <see cref="ToolCommandLine"/> split them (options by name, positionals in order),
    /// with the option parsers the commands share, so an option that several commands take (<c>--split</c>,
    /// <c>--out</c>, a folder, a whole number) is read and refused the same way everywhere. Usage mistakes are
    /// collected in <see cref="Errors"/>; the command runs only when there is none.
    /// </summary>
    public sealed class ToolArguments
    {
        readonly Dictionary<string, string> _options;

        internal ToolArguments(string command, Dictionary<string, string> options, List<string> positionals, List<string> errors)
        {
            Command = command;
            _options = options;
            Positionals = positionals;
            Errors = errors;
        }

        /// <summary>The command's name, as typed.</summary>
        public string Command { get; }

        /// <summary>The arguments that are not options, in the order given.</summary>
        public IReadOnlyList<string> Positionals { get; }

        /// <summary>The usage mistakes found so far, in the order they are printed.</summary>
        public List<string> Errors { get; }

        public void Error(string message) => Errors.Add(message);

        /// <summary>The value of <c>--name</c>; a flag's value is "true", unless one was given with '='.</summary>
        public bool TryGet(string name, out string value) => _options.TryGetValue(name, out value);

        public bool Has(string name) => _options.ContainsKey(name);

        /// <summary>One error per option the command does not take, in the order they were given.</summary>
        public void RefuseUnknownOptions(params string[] known)
        {
            foreach (var name in _options.Keys)
                if (Array.IndexOf(known, name) < 0)
                    Errors.Add(Command + " does not know the option --" + name + ".");
        }

        /// <summary>The one positional argument (a folder); <paramref name="mistake"/> and null when there is none or more.</summary>
        public string OnePositional(string mistake)
        {
            if (Positionals.Count == 1) return Positionals[0];
            Errors.Add(mistake);
            return null;
        }

        /// <summary>A flag such as <c>--depths</c>: whether it was given; <c>--depths=yes</c> is a mistake.</summary>
        public bool Flag(string name)
        {
            if (!TryGet(name, out var value)) return false;
            if (value != "true") Errors.Add("--" + name + " takes no value ('" + value + "').");
            return true;
        }

        /// <summary>A path the command cannot do without (<c>--out</c> of plan and merge): <paramref name="missing"/> when absent or blank.</summary>
        public string RequiredPath(string name, string missing)
        {
            TryGet(name, out var value);
            if (string.IsNullOrWhiteSpace(value)) Errors.Add(missing);
            return value;
        }

        /// <summary>A path that may be left out (<c>--out</c> of convert and evaluate, <c>--json</c>): null when absent; <paramref name="empty"/> when given blank.</summary>
        public string OptionalPath(string name, string empty)
        {
            if (!TryGet(name, out var value)) return null;
            if (!string.IsNullOrWhiteSpace(value)) return value;
            Errors.Add(empty);
            return null;
        }

        /// <summary><c>--split train|val|test</c>, exactly as written (lower case): the split's name, or null when absent or not a split.</summary>
        public string Split()
        {
            if (!TryGet("split", out var split)) return null;
            if (DatasetSplits.TryParse(split, out _)) return split;
            Errors.Add("--split = " + split + ": is not train, val or test.");
            return null;
        }

        /// <summary>
        /// A whole number of at least <paramref name="minimum"/> (digits only: no sign, no spaces, no thousands
        /// separator): null when absent; <paramref name="mistake"/>(value) and null when it is not one.
        /// </summary>
        public int? WholeNumber(string name, int minimum, Func<string, string> mistake)
        {
            if (!TryGet(name, out var text)) return null;
            if (int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out var n) && n >= minimum) return n;
            Errors.Add(mistake(text));
            return null;
        }

        /// <summary>A finite number &gt; 0 (invariant culture): null when absent; <paramref name="mistake"/>(value) and null when it is not one.</summary>
        public double? PositiveNumber(string name, Func<string, string> mistake)
        {
            if (!TryGet(name, out var text)) return null;
            if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var x) && x > 0 && !double.IsInfinity(x)) return x;
            Errors.Add(mistake(text));
            return null;
        }

        /// <summary>For the command lines the Dataset Tools build: a folder they cannot leave out.</summary>
        internal static string Required(string folder) =>
            string.IsNullOrWhiteSpace(folder) ? throw new ArgumentException("a folder is needed", nameof(folder)) : folder;
    }
}
