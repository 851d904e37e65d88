using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>What one labelled object (one instance id) is made of (Documentation~/labels.md).</summary>
    public enum InstanceRule
    {
        /// <summary>Each GameObject with a renderer under the target is its own object.</summary>
        Renderer,
        /// <summary>
        /// Each prefab instance under the target is one object: the outermost prefab instance root below the target that
        /// holds the renderer (a car prefab is one object, not its forty meshes); renderers in no prefab instance count
        /// one by one, as with <see cref="Renderer"/>.
        /// </summary>
        PrefabInstance,
        /// <summary>Each direct child of the target is one object, with everything below it; renderers on the target itself are one more object.</summary>
        TargetChild,
    }

    /// <summary>Which property of an object its class comes from.</summary>
    public enum ClassSource
    {
        /// <summary>The instance root's tag (Unity's <c>GameObject.tag</c>).</summary>
        Tag,
        /// <summary>The instance root's layer name (<c>LayerMask.LayerToName</c>).</summary>
        Layer,
        /// <summary>The prefab asset the instance comes from (its project path, e.g. <c>Assets/Props/Car.prefab</c>).</summary>
        Prefab,
        /// <summary>The instance root's name, matched against the patterns of <see cref="LabelSettings.Classes"/>.</summary>
        Name,
    }

    /// <summary>One class rule: objects whose class property matches <see cref="Match"/> belong to class <see cref="Class"/>.</summary>
    [Serializable]
    public sealed class ClassRule
    {
        /// <summary>
        /// The tag, layer name, prefab asset path or object name to match; <c>*</c> stands for any run of characters and
        /// <c>?</c> for one (<see cref="LabelPattern"/>). Matched case-sensitively, as Unity's tags and layers are.
        /// </summary>
        public string Match = "";

        /// <summary>The class name written to labels.json.</summary>
        public string Class = "";

        public ClassRule() { }

        public ClassRule(string match, string className)
        {
            Match = match;
            Class = className;
        }

        public ClassRule Clone() => (ClassRule)MemberwiseClone();
    }

    /// <summary>
    /// The <c>"labels"</c> section of the settings: instance and semantic id maps for every view of every split
    /// (<c>r_&lt;i&gt;_instance_0000.png</c>, <c>r_&lt;i&gt;_semantic_0000.png</c>) and <c>labels.json</c>. Nothing is added
    /// to the scene: objects are told apart by the hierarchy, classes by tag, layer, prefab or name, mapped here.
    /// </summary>
    [Serializable]
    public sealed class LabelSettings
    {
        /// <summary>The most instance or class ids a capture may hold: a 16-bit PNG's values, 0 being background.</summary>
        public const int MaxIds = 65535;

        /// <summary>The most class rules a settings file may hold.</summary>
        public const int MaxRules = 4096;

        /// <summary>Writes the id maps and labels.json. Off by default; a settings file turns it on with a <c>"labels"</c> object.</summary>
        public bool Enabled;

        public InstanceRule Instances = InstanceRule.PrefabInstance;

        public ClassSource ClassFrom = ClassSource.Tag;

        /// <summary>
        /// The class rules in order; the first rule that matches decides. With no rules, every distinct tag, layer or
        /// prefab is a class of its own, named after it (not possible with <see cref="ClassSource.Name"/>).
        /// </summary>
        public List<ClassRule> Classes = new List<ClassRule>();

        /// <summary>
        /// The class of objects no rule matches (and, with no rules, of objects with no prefab); empty: they are
        /// class 0 in the semantic map, like the background (they keep their instance ids).
        /// </summary>
        public string OtherClass = "";

        public LabelSettings Clone()
        {
            var copy = (LabelSettings)MemberwiseClone();
            copy.Classes = new List<ClassRule>();
            if (Classes != null) foreach (var rule in Classes) copy.Classes.Add(rule?.Clone());
            return copy;
        }
    }
}
