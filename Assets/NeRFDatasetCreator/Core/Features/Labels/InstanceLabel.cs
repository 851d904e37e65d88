using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>One labelled object: a row of labels.json's <c>instances</c>.</summary>
    public sealed class InstanceLabel
    {
        public InstanceLabel(int id, string name, string path, IReadOnlyList<int> siblingPath, int classId, string className)
        {
            Id = id;
            Name = name ?? "";
            Path = path ?? "";
            SiblingPath = siblingPath ?? new int[0];
            ClassId = classId;
            ClassName = className ?? "";
        }

        /// <summary>The value of its pixels in every <c>r_&lt;i&gt;_instance_0000.png</c>, 1…65535.</summary>
        public int Id { get; }

        /// <summary>The instance root's GameObject name.</summary>
        public string Name { get; }

        /// <summary>Its hierarchy path, names joined by "/" from the scene root (as Unity's hierarchy shows it).</summary>
        public string Path { get; }

        /// <summary>The sibling indices along <see cref="Path"/>: what tells same-named siblings apart, and the ids' order.</summary>
        public IReadOnlyList<int> SiblingPath { get; }

        /// <summary>Its class id (its pixels' value in the semantic maps); 0 when it has no class.</summary>
        public int ClassId { get; }

        /// <summary>The class name; empty when <see cref="ClassId"/> is 0.</summary>
        public string ClassName { get; }

        /// <summary>The display colour, "#rrggbb" (<see cref="LabelColours"/>).</summary>
        public string Colour => LabelColours.Hex(Id);

        /// <summary>The identity of the object across captures: sibling path and names (<see cref="LabelKey"/>).</summary>
        public string Key => LabelKey.Of(SiblingPath, Path);
    }

    /// <summary>One class: a row of labels.json's <c>classes</c>.</summary>
    public sealed class ClassLabel
    {
        public ClassLabel(int id, string name)
        {
            Id = id;
            Name = name ?? "";
        }

        /// <summary>The value of its pixels in every <c>r_&lt;i&gt;_semantic_0000.png</c>, 1…65535.</summary>
        public int Id { get; }

        public string Name { get; }

        public string Colour => LabelColours.Hex(Id);
    }
}
