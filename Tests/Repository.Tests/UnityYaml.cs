using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using YamlDotNet.RepresentationModel;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// A Unity YAML file (scene, .anim) read with YamlDotNet: one document per object, its tag
    /// <c>!u!&lt;class ID&gt;</c> (tag:unity3d.com,2011:&lt;class ID&gt;) and its anchor <c>&amp;&lt;file ID&gt;</c>, whose single key
    /// is the class name (Unity Manual, "Format of Text Serialized files"). Reading it with a real YAML parser also
    /// checks that the hand-written files are well-formed YAML.
    /// </summary>
    sealed class UnityYaml
    {
        const string TagPrefix = "tag:unity3d.com,2011:";

        public sealed class UnityObject
        {
            public int ClassId;
            public string FileId;
            public string ClassName;
            public YamlMappingNode Body;
        }

        public List<UnityObject> Objects { get; } = new List<UnityObject>();

        public static UnityYaml Load(string path)
        {
            var stream = new YamlStream();
            using (var reader = new StringReader(File.ReadAllText(path))) stream.Load(reader);
            var file = new UnityYaml();
            foreach (var document in stream.Documents)
            {
                var root = (YamlMappingNode)document.RootNode;
                var tag = root.Tag.Value;
                if (!tag.StartsWith(TagPrefix, StringComparison.Ordinal)) throw new InvalidDataException(path + ": a document tagged " + tag);
                var entry = root.Children.Single();
                file.Objects.Add(new UnityObject
                {
                    ClassId = int.Parse(tag.Substring(TagPrefix.Length), CultureInfo.InvariantCulture),
                    FileId = root.Anchor.Value,
                    ClassName = ((YamlScalarNode)entry.Key).Value,
                    Body = (YamlMappingNode)entry.Value,
                });
            }
            return file;
        }

        public UnityObject ById(string fileId) => Objects.Single(o => o.FileId == fileId);

        public IEnumerable<UnityObject> OfClass(int classId) => Objects.Where(o => o.ClassId == classId);

        /// <summary>The GameObject named <paramref name="name"/> (exactly one).</summary>
        public UnityObject GameObject(string name) => OfClass(1).Single(o => Text(o.Body, "m_Name") == name);

        /// <summary>The component of <paramref name="classId"/> on a GameObject, through the GameObject's m_Component list.</summary>
        public UnityObject Component(UnityObject gameObject, int classId) =>
            Sequence(gameObject.Body, "m_Component")
                .Select(c => ById(Reference(((YamlMappingNode)c)["component"]).FileId))
                .Single(c => c.ClassId == classId);

        public static YamlNode Node(YamlMappingNode map, string key) => map.Children[new YamlScalarNode(key)];

        public static string Text(YamlMappingNode map, string key) => ((YamlScalarNode)Node(map, key)).Value;

        public static double Number(YamlMappingNode map, string key) => Number(Node(map, key));

        public static double Number(YamlNode node) => double.Parse(((YamlScalarNode)node).Value, NumberStyles.Float, CultureInfo.InvariantCulture);

        public static YamlMappingNode Map(YamlMappingNode map, string key) => (YamlMappingNode)Node(map, key);

        public static IReadOnlyList<YamlNode> Sequence(YamlMappingNode map, string key) => ((YamlSequenceNode)Node(map, key)).Children.ToList();

        /// <summary>A <c>{x: …, y: …, z: …}</c> flow mapping.</summary>
        public static double[] Vector3(YamlNode node)
        {
            var map = (YamlMappingNode)node;
            return new[] { Number(map, "x"), Number(map, "y"), Number(map, "z") };
        }

        /// <summary>An object reference <c>{fileID: …, guid: …, type: …}</c> (guid and type absent within the same file).</summary>
        public static ObjectReference Reference(YamlNode node)
        {
            var map = (YamlMappingNode)node;
            string Optional(string key) => map.Children.TryGetValue(new YamlScalarNode(key), out var value) ? ((YamlScalarNode)value).Value : null;
            return new ObjectReference(Optional("fileID"), Optional("guid"), Optional("type"));
        }

        public readonly struct ObjectReference
        {
            public ObjectReference(string fileId, string guid, string type)
            {
                FileId = fileId;
                Guid = guid;
                Type = type;
            }

            public string FileId { get; }
            public string Guid { get; }
            public string Type { get; }

            public override string ToString() => "{fileID: " + FileId + ", guid: " + Guid + ", type: " + Type + "}";
        }
    }
}
