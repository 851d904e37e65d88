using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The capture's instance and class ids (labels.json). Ids come from the scene's hierarchy, never from Unity's
    /// instance IDs: <see cref="Build"/> groups the described renderers into objects by <see cref="LabelSettings.Instances"/>,
    /// sorts the objects in hierarchy order (<see cref="LabelKey.Compare"/>) and numbers them 1, 2, 3…; the same scene
    /// always gives the same ids, in every view, split, shard and re-capture. Objects that appear later in a dynamic
    /// capture (spawned, enabled) get the next free ids when <see cref="AddAppearing"/> first sees them, in hierarchy
    /// order within a time step; time steps are visited in order, so this too is the same in every capture.
    /// Not thread-safe while objects are being added; reading is.
    /// </summary>
    public sealed class LabelTable
    {
        readonly LabelSettings _settings;
        readonly List<InstanceLabel> _instances = new List<InstanceLabel>();
        readonly List<ClassLabel> _classes = new List<ClassLabel>();
        readonly Dictionary<string, int> _idOfKey = new Dictionary<string, int>(StringComparer.Ordinal);
        readonly Dictionary<long, int> _idOfSession = new Dictionary<long, int>();
        readonly Dictionary<string, int> _classIdOfName = new Dictionary<string, int>(StringComparer.Ordinal);
        ushort[] _classOfInstance = new ushort[1];

        LabelTable(LabelSettings settings)
        {
            _settings = settings;
        }

        /// <summary>
        /// The table of the objects <paramref name="renderers"/> make up (the scene at the capture's start, or its first
        /// time step). Throws <see cref="InvalidParameterException"/> naming <c>labels</c> when there are more than
        /// 65535 objects or classes.
        /// </summary>
        public static LabelTable Build(LabelSettings settings, IEnumerable<SceneObjectInfo> renderers)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var table = new LabelTable(settings.Clone());
            // Classes named by rules come first, in rule order: their ids do not depend on what the scene holds.
            foreach (var rule in table._settings.Classes)
                if (rule != null && !string.IsNullOrEmpty(rule.Class)) table.ClassId(rule.Class);
            if (!string.IsNullOrEmpty(table._settings.OtherClass) && table._settings.Classes.Count > 0) table.ClassId(table._settings.OtherClass);
            table.AddAppearing(renderers ?? Enumerable.Empty<SceneObjectInfo>());
            return table;
        }

        /// <summary>A table read back from labels.json (<see cref="LabelsJson"/>): ids exactly as written.</summary>
        internal static LabelTable FromRows(LabelSettings settings, IEnumerable<ClassLabel> classes, IEnumerable<InstanceLabel> instances)
        {
            var table = new LabelTable(settings ?? new LabelSettings());
            foreach (var c in classes.OrderBy(c => c.Id))
            {
                table._classes.Add(c);
                table._classIdOfName[c.Name] = c.Id;
            }
            foreach (var i in instances.OrderBy(i => i.Id))
            {
                table._instances.Add(i);
                table._idOfKey[i.Key] = i.Id;
            }
            table.RebuildClassLookup();
            return table;
        }

        public LabelSettings Settings => _settings;

        /// <summary>Every object, by id (1, 2, 3…: the list's index + 1).</summary>
        public IReadOnlyList<InstanceLabel> Instances => _instances;

        /// <summary>Every class, by id (1, 2, 3…: the list's index + 1).</summary>
        public IReadOnlyList<ClassLabel> Classes => _classes;

        /// <summary>
        /// Adds the objects of <paramref name="renderers"/> not in the table yet (a dynamic capture calls it at each time
        /// step, in time order, before the step's id pass). An object the table knows by its
        /// <see cref="SceneObjectInfo.SessionId"/> keeps its id even if its hierarchy path changed. Returns how many ids were added.
        /// </summary>
        public int AddAppearing(IEnumerable<SceneObjectInfo> renderers)
        {
            if (renderers == null) throw new ArgumentNullException(nameof(renderers));
            var fresh = new Dictionary<string, Candidate>(StringComparer.Ordinal);
            var freshSessions = new List<KeyValuePair<long, string>>();
            foreach (var renderer in renderers)
            {
                var c = Candidate.Of(renderer, _settings);
                if (_idOfKey.TryGetValue(c.Key, out var existing))
                {
                    if (c.SessionId != 0) _idOfSession[c.SessionId] = existing;
                    continue;
                }
                if (c.SessionId != 0 && _idOfSession.TryGetValue(c.SessionId, out var known))
                {
                    _idOfKey[c.Key] = known; // moved in the hierarchy: the same object
                    continue;
                }
                if (c.SessionId != 0) freshSessions.Add(new KeyValuePair<long, string>(c.SessionId, c.Key));
                if (!fresh.ContainsKey(c.Key)) fresh.Add(c.Key, c);
            }
            var ordered = fresh.Values.ToList();
            ordered.Sort((a, b) => LabelKey.Compare(a.SiblingPath, a.Path, b.SiblingPath, b.Path));
            if (_instances.Count + ordered.Count > LabelSettings.MaxIds)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("labels.instances", InstanceRules.Name(_settings.Instances),
                        "gives " + (_instances.Count + ordered.Count).ToString(CultureInfo.InvariantCulture) + " objects; a 16-bit id map holds at most " +
                        LabelSettings.MaxIds.ToString(CultureInfo.InvariantCulture) + ".",
                        "Use \"prefab\" or \"child\" so that a whole object is one id, or capture a smaller target."),
                });
            foreach (var c in ordered)
            {
                var classId = ClassOf(c.ClassValue, c.ClassValueIsEmpty);
                var id = _instances.Count + 1;
                _instances.Add(new InstanceLabel(id, c.Name, c.Path, c.SiblingPath, classId, classId == 0 ? "" : _classes[classId - 1].Name));
                _idOfKey.Add(c.Key, id);
            }
            foreach (var session in freshSessions) _idOfSession[session.Key] = _idOfKey[session.Value];
            RebuildClassLookup();
            return ordered.Count;
        }

        /// <summary>The instance id of the object <paramref name="renderer"/> belongs to; 0 when the table does not hold it.</summary>
        public int InstanceIdOf(SceneObjectInfo renderer)
        {
            var c = Candidate.Of(renderer, _settings);
            if (_idOfKey.TryGetValue(c.Key, out var id)) return id;
            return c.SessionId != 0 && _idOfSession.TryGetValue(c.SessionId, out id) ? id : 0;
        }

        /// <summary>The class id of instance <paramref name="instanceId"/>; 0 for the background, unclassed objects and unknown ids.</summary>
        public int ClassIdOf(int instanceId) =>
            instanceId > 0 && instanceId < _classOfInstance.Length ? _classOfInstance[instanceId] : 0;

        /// <summary>
        /// The class id of every instance id, index = instance id (index 0, the background, is 0): what
        /// <see cref="IdMajority"/> maps samples through for the semantic map. A new array after each <see cref="AddAppearing"/>
        /// that added ids, so a reader holding the old one is never disturbed.
        /// </summary>
        public ushort[] ClassOfInstance => _classOfInstance;

        /// <summary>The instance with this id, or null.</summary>
        public InstanceLabel Instance(int id) => id >= 1 && id <= _instances.Count ? _instances[id - 1] : null;

        /// <summary>The class with this id, or null.</summary>
        public ClassLabel Class(int id) => id >= 1 && id <= _classes.Count ? _classes[id - 1] : null;

        void RebuildClassLookup()
        {
            var max = _instances.Count == 0 ? 0 : _instances.Max(i => i.Id);
            var lookup = new ushort[max + 1];
            foreach (var i in _instances) lookup[i.Id] = (ushort)i.ClassId;
            _classOfInstance = lookup;
        }

        int ClassOf(string value, bool empty)
        {
            var rules = _settings.Classes;
            if (rules.Count > 0)
            {
                foreach (var rule in rules)
                    if (rule != null && !empty && LabelPattern.Matches(rule.Match, value)) return ClassId(rule.Class);
                return string.IsNullOrEmpty(_settings.OtherClass) ? 0 : ClassId(_settings.OtherClass);
            }
            // No rules: each distinct value is a class of its own, in order of first appearance (hierarchy order).
            if (empty) return string.IsNullOrEmpty(_settings.OtherClass) ? 0 : ClassId(_settings.OtherClass);
            return ClassId(value);
        }

        int ClassId(string name)
        {
            if (_classIdOfName.TryGetValue(name, out var id)) return id;
            if (_classes.Count >= LabelSettings.MaxIds)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("labels.classFrom", ClassSources.Name(_settings.ClassFrom), "gives more than " + LabelSettings.MaxIds.ToString(CultureInfo.InvariantCulture) + " classes.",
                        "Map values to fewer classes with labels.classes."),
                });
            id = _classes.Count + 1;
            _classes.Add(new ClassLabel(id, name));
            _classIdOfName.Add(name, id);
            return id;
        }

        /// <summary>The object a renderer belongs to, by the instance rule, and its class property.</summary>
        sealed class Candidate
        {
            public string Key, Name, Path, ClassValue;
            public bool ClassValueIsEmpty;
            public int[] SiblingPath;
            public long SessionId;

            public static Candidate Of(SceneObjectInfo renderer, LabelSettings settings)
            {
                if (renderer == null) throw new ArgumentNullException(nameof(renderer));
                var chain = renderer.Chain;
                var rootIndex = InstanceRootIndex(renderer, settings.Instances);
                var siblings = new int[rootIndex + 1];
                var names = new string[rootIndex + 1];
                for (var i = 0; i <= rootIndex; i++)
                {
                    siblings[i] = chain[i].SiblingIndex;
                    names[i] = chain[i].Name;
                }
                var root = chain[rootIndex];
                var path = string.Join("/", names);
                string value;
                switch (settings.ClassFrom)
                {
                    case ClassSource.Tag: value = root.Tag; break;
                    case ClassSource.Layer: value = root.Layer; break;
                    case ClassSource.Prefab: value = PrefabOf(renderer, rootIndex); break;
                    default: value = root.Name; break;
                }
                return new Candidate
                {
                    Key = LabelKey.Of(siblings, path),
                    Name = root.Name,
                    Path = path,
                    SiblingPath = siblings,
                    ClassValue = value,
                    ClassValueIsEmpty = value.Length == 0,
                    SessionId = renderer.SessionId,
                };
            }

            /// <summary>The index on the chain of the GameObject that is the renderer's object.</summary>
            static int InstanceRootIndex(SceneObjectInfo renderer, InstanceRule rule)
            {
                var chain = renderer.Chain;
                var last = chain.Count - 1;
                switch (rule)
                {
                    case InstanceRule.TargetChild:
                        // The target's direct child on the chain; the target itself when the renderer is on it.
                        return Math.Min(renderer.TargetDepth, last);
                    case InstanceRule.PrefabInstance:
                        // The outermost prefab instance root strictly below the target.
                        for (var i = renderer.TargetDepth; i <= last; i++)
                            if (chain[i].IsPrefabInstanceRoot) return i;
                        return last;
                    default:
                        return last;
                }
            }

            /// <summary>The prefab asset of the outermost prefab instance on the chain from the target down to the object's root (or above it).</summary>
            static string PrefabOf(SceneObjectInfo renderer, int rootIndex)
            {
                var chain = renderer.Chain;
                for (var i = renderer.TargetDepth; i <= rootIndex; i++)
                    if (chain[i].IsPrefabInstanceRoot) return chain[i].PrefabAsset;
                // An object inside a prefab instance the target itself is part of: its nearest enclosing prefab.
                for (var i = Math.Min(renderer.TargetDepth - 1, rootIndex); i >= 0; i--)
                    if (chain[i].IsPrefabInstanceRoot) return chain[i].PrefabAsset;
                return "";
            }
        }
    }
}
