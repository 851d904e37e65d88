using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --object &lt;name|id&gt;</c>: which labelled object of labels.json the user means. A whole number is an
    /// instance id; anything else is matched against the hierarchy paths (exactly, then as the path's end after a "/")
    /// and the object names. No match is an error with a did-you-mean; several matches are an error listing them with
    /// their ids and paths, so the user can pick one exactly.
    /// </summary>
    public static class ObjectSelection
    {
        public const string Option = "--object";

        /// <summary>Candidates listed at most in an "ambiguous" error.</summary>
        const int MaxListed = 8;

        public static InstanceLabel Find(LabelTable table, string nameOrId)
        {
            if (table == null) throw new ArgumentNullException(nameof(table));
            var given = (nameOrId ?? "").Trim();
            if (given.Length == 0) throw Refused(given, "is empty.", "Give an object's name, hierarchy path or instance id from labels.json.");
            if (int.TryParse(given, NumberStyles.None, CultureInfo.InvariantCulture, out var id))
            {
                var byId = table.Instance(id);
                if (byId != null) return byId;
                throw Refused(given, "is not an instance id of this dataset: labels.json has ids 1 to " + table.Instances.Count.ToString(CultureInfo.InvariantCulture) + ".",
                    "Use an id from labels.json's \"instances\", or the object's name.");
            }
            var trimmed = given.Trim('/');
            var matches = table.Instances.Where(i => i.Path == trimmed).ToList();
            if (matches.Count == 0) matches = table.Instances.Where(i => i.Path.EndsWith("/" + trimmed, StringComparison.Ordinal)).ToList();
            if (matches.Count == 0) matches = table.Instances.Where(i => i.Name == trimmed).ToList();
            if (matches.Count == 0) matches = table.Instances.Where(i => string.Equals(i.Name, trimmed, StringComparison.OrdinalIgnoreCase)).ToList();
            if (matches.Count == 1) return matches[0];
            if (matches.Count > 1)
                throw Refused(given, "names " + matches.Count.ToString(CultureInfo.InvariantCulture) + " objects: " +
                    string.Join("; ", matches.Take(MaxListed).Select(Describe)) + (matches.Count > MaxListed ? "; …" : "") + ".",
                    "Give the instance id or the full hierarchy path of the one you mean.");
            var names = table.Instances.Select(i => i.Name).Concat(table.Instances.Select(i => i.Path)).Distinct().ToList();
            throw Refused(given, "is not the name, hierarchy path or instance id of a labelled object in this dataset." + SpellingSuggestion.Sentence(trimmed, names),
                "See labels.json's \"instances\" for the objects and their ids.");
        }

        public static string Describe(InstanceLabel label) =>
            "id " + label.Id.ToString(CultureInfo.InvariantCulture) + " \"" + label.Path + "\"" + (label.ClassName.Length > 0 ? " (" + label.ClassName + ")" : "");

        static InvalidParameterException Refused(string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(Option, value, reason, fix) });
    }
}
