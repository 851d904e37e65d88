using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Review R4-4: a whole-scene capture with two loaded scenes made from one template, each holding <c>0:Room/0:Wall</c>
    /// (two distinct walls). Without the scene in the key they were one object with one id; with <see cref="LabelScenes"/>
    /// they are two, named by their scene, for every instance rule, and a labels.json written from them reads back with the
    /// same keys. One loaded scene keeps the keys and paths of earlier versions.
    /// </summary>
    public class LabelScenesTests
    {
        /// <summary>The wall of a room scene: root Room (index 0 among its scene's roots), child Wall (index 0).</summary>
        static SceneObjectInfo Wall(long session) =>
            new SceneObjectInfo(new[] { new SceneNode("Room", 0, "Untagged", "Default"), new SceneNode("Wall", 0, "Untagged", "Default") }, 0, session);

        static List<SceneObjectInfo> TwoRooms() => new List<SceneObjectInfo>
        {
            LabelScenes.InScene(Wall(101), "Room_01", 0),
            LabelScenes.InScene(Wall(202), "Room_02", 1),
        };

        [TestCase(InstanceRule.Renderer, "Room_01/Room/Wall", "Room_02/Room/Wall")]
        [TestCase(InstanceRule.TargetChild, "Room_01/Room", "Room_02/Room")]
        [TestCase(InstanceRule.PrefabInstance, "Room_01/Room/Wall", "Room_02/Room/Wall")]
        public void TwoScenesWithTheSameRootNameAndIndexGiveTwoObjects(InstanceRule rule, string first, string second)
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(rule, ClassSource.Name), TwoRooms());
            Assert.That(table.Instances.Select(i => i.Path), Is.EqualTo(new[] { first, second }));
            Assert.That(TwoRooms().Select(table.InstanceIdOf), Is.EqualTo(new[] { 1, 2 }));
            // The class comes from the object, never from the scene node.
            Assert.That(table.Instances.Select(i => i.ClassName).Distinct(), Is.EqualTo(new[] { rule == InstanceRule.TargetChild ? "Room" : "Wall" }));
        }

        [Test]
        public void WithoutTheSceneTheTwoWallsWereOneObject()
        {
            // What happened before: the same chain from two scenes is one key, one id.
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Name), new[] { Wall(101), Wall(202) });
            Assert.That(table.Instances, Has.Count.EqualTo(1));
        }

        [Test]
        public void TheScenesIndexOrdersTheIdsAndTellsSameNamedScenesApart()
        {
            // Two scenes called "Room" (from two folders), loaded second and first.
            var infos = new[] { LabelScenes.InScene(Wall(1), "Room", 1), LabelScenes.InScene(Wall(2), "Room", 0) };
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Name), infos);
            Assert.That(table.Instances.Select(i => string.Join(".", i.SiblingPath)), Is.EqualTo(new[] { "0.0.0", "1.0.0" }));
            Assert.That(infos.Select(table.InstanceIdOf), Is.EqualTo(new[] { 2, 1 }), "hierarchy order: the first loaded scene first");
        }

        [Test]
        public void LabelsJsonKeepsTheSceneQualifiedKeys()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Name), TwoRooms());
            var back = LabelsJson.Parse(LabelsJson.Write(table), "labels.json");
            Assert.That(back.Instances.Select(i => i.Key), Is.EqualTo(new[] { "0:Room_01/0:Room/0:Wall", "1:Room_02/0:Room/0:Wall" }));
            Assert.That(LabelsJson.Difference(table, back), Is.Null);
        }

        [Test]
        public void AnUnsavedSceneIsCalledUntitledAndOneLoadedSceneIsNotQualified()
        {
            Assert.That(LabelScenes.InScene(Wall(1), "", 2).Chain[0].Name, Is.EqualTo("Untitled"));
            Assert.That(LabelScenes.Qualifies(1), Is.False, "a single-scene capture keeps the keys earlier versions wrote");
            Assert.That(LabelScenes.Qualifies(2), Is.True);
        }
    }
}
