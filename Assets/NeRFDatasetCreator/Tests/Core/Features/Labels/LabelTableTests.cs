using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class LabelTableTests
    {
        static string[] Paths(LabelTable table) => table.Instances.Select(i => i.Path + "#" + string.Join(".", i.SiblingPath)).ToArray();

        [Test]
        public void EachRendererIsAnObjectNumberedInHierarchyOrder()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Tag), LabelHierarchy.Renderers());
            Assert.That(Paths(table), Is.EqualTo(new[]
            {
                "City/Car/Body#0.0.0", "City/Car/Wheel#0.0.1", "City/Tree#0.1", "City/Car/Body#0.2.0", "City/Lamp#0.3",
            }));
            Assert.That(table.Instances.Select(i => i.Id), Is.EqualTo(new[] { 1, 2, 3, 4, 5 }));
        }

        [Test]
        public void APrefabInstanceIsOneObject()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag), LabelHierarchy.Renderers());
            Assert.That(Paths(table), Is.EqualTo(new[] { "City/Car#0.0", "City/Tree#0.1", "City/Car#0.2", "City/Lamp#0.3" }));
            var renderers = LabelHierarchy.Renderers();
            // Both renderers of the first car are object 1; the second car's body is object 3.
            Assert.That(renderers.Select(table.InstanceIdOf), Is.EqualTo(new[] { 1, 1, 2, 3, 4 }));
        }

        [Test]
        public void ADirectChildOfTheTargetIsOneObjectAndTheSceneRootsAreTheChildrenOfAWholeSceneCapture()
        {
            var child = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.TargetChild, ClassSource.Tag), LabelHierarchy.Renderers());
            Assert.That(Paths(child), Is.EqualTo(new[] { "City/Car#0.0", "City/Tree#0.1", "City/Car#0.2", "City/Lamp#0.3" }));

            // Target depth 0 (the whole scene): City is one object, and a second root Sun another.
            var scene = LabelHierarchy.Renderers().Select(r => new SceneObjectInfo(r.Chain, 0, r.SessionId)).ToList();
            scene.Add(new SceneObjectInfo(new[] { new SceneNode("Sun", 1) }, 0));
            var whole = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.TargetChild, ClassSource.Tag), scene);
            Assert.That(Paths(whole), Is.EqualTo(new[] { "City#0", "Sun#1" }));
        }

        [Test]
        public void IdsDoNotDependOnTheOrderTheRenderersAreFoundInNorOnSessionIds()
        {
            var settings = LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Tag);
            var first = LabelTable.Build(settings, LabelHierarchy.Renderers());
            // Another capture (another shard, a re-capture): other instance IDs, another discovery order.
            var shuffled = LabelHierarchy.Renderers().AsEnumerable().Reverse()
                .Select(r => new SceneObjectInfo(r.Chain, r.TargetDepth, r.SessionId + 1000)).ToList();
            var second = LabelTable.Build(settings, shuffled);
            Assert.That(LabelsJson.Difference(first, second), Is.Null);
            Assert.That(LabelsJson.Write(second), Is.EqualTo(LabelsJson.Write(first)));
        }

        [Test]
        public void ClassesAreTheTagsInOrderOfFirstAppearanceWithoutRules()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag), LabelHierarchy.Renderers());
            Assert.That(table.Classes.Select(c => c.Id + ":" + c.Name), Is.EqualTo(new[] { "1:Vehicle", "2:Untagged", "3:Light" }));
            Assert.That(table.Instances.Select(i => i.ClassName), Is.EqualTo(new[] { "Vehicle", "Untagged", "Vehicle", "Light" }));
            Assert.That(table.ClassOfInstance, Is.EqualTo(new ushort[] { 0, 1, 2, 1, 3 }));
        }

        [Test]
        public void RulesNameTheClassesInRuleOrderAndUnmatchedObjectsGetTheOtherClassOrNone()
        {
            var settings = LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Name,
                new ClassRule("Tree", "vegetation"), new ClassRule("C?r*", "car"), new ClassRule("Bus*", "car"));
            var table = LabelTable.Build(settings, LabelHierarchy.Renderers());
            Assert.That(table.Classes.Select(c => c.Name), Is.EqualTo(new[] { "vegetation", "car" }));
            Assert.That(table.Instances.Select(i => i.ClassId), Is.EqualTo(new[] { 2, 1, 2, 0 })); // the lamp matches nothing

            settings.OtherClass = "other";
            var withOther = LabelTable.Build(settings, LabelHierarchy.Renderers());
            Assert.That(withOther.Classes.Select(c => c.Name), Is.EqualTo(new[] { "vegetation", "car", "other" }));
            Assert.That(withOther.Instances.Select(i => i.ClassId), Is.EqualTo(new[] { 2, 1, 2, 3 }));
        }

        [Test]
        public void ClassesFromLayersAndPrefabs()
        {
            var layers = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Layer), LabelHierarchy.Renderers());
            Assert.That(layers.Instances.Select(i => i.ClassName), Is.EqualTo(new[] { "Props", "Default", "Props", "Props" }));
            var prefabs = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Prefab, new ClassRule("*/Car.prefab", "car")), LabelHierarchy.Renderers());
            // Each body and wheel is its own object, classed by the car prefab it belongs to; tree and lamp have none.
            Assert.That(prefabs.Instances.Select(i => i.ClassId), Is.EqualTo(new[] { 1, 1, 0, 1, 0 }));
        }

        [Test]
        public void ObjectsAppearingLaterTakeTheNextIdsAndAMovedObjectKeepsItsId()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag), LabelHierarchy.Renderers());
            // Time step 2: a bus is spawned at the end of City and a crate before it; the first car moves under the lamp.
            var step = LabelHierarchy.Renderers().Skip(2).ToList();
            step.Add(LabelHierarchy.Renderer(21, LabelHierarchy.City, new SceneNode("Bus", 5, "Vehicle", "Props", "Assets/Props/Bus.prefab"), new SceneNode("Body", 0)));
            step.Add(LabelHierarchy.Renderer(22, LabelHierarchy.City, new SceneNode("Crate", 4, "Prop", "Props")));
            step.Add(new SceneObjectInfo(new[] { LabelHierarchy.City, new SceneNode("Lamp", 3, "Light", "Props"), LabelHierarchy.Car(0), new SceneNode("Body", 0) }, 1, 11));
            Assert.That(table.AddAppearing(step), Is.EqualTo(2));
            Assert.That(Paths(table).Skip(4), Is.EqualTo(new[] { "City/Crate#0.4", "City/Bus#0.5" }));
            Assert.That(table.InstanceIdOf(step[step.Count - 1]), Is.EqualTo(1), "the moved car keeps id 1");
            Assert.That(table.Instances[4].ClassName, Is.EqualTo("Prop"));
            Assert.That(table.ClassOfInstance.Length, Is.EqualTo(7));
            Assert.That(table.AddAppearing(step), Is.EqualTo(0), "seen objects are not added again");
        }

        [Test]
        public void MoreObjectsThanASixteenBitMapHoldsAreRefusedNamingTheKey()
        {
            var many = Enumerable.Range(0, LabelSettings.MaxIds + 1)
                .Select(i => new SceneObjectInfo(new[] { LabelHierarchy.City, new SceneNode("Rock", i) }, 1)).ToList();
            var e = Assert.Throws<InvalidParameterException>(() => LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Tag), many));
            Assert.That(e.Problems[0].Field, Is.EqualTo("labels.instances"));
            Assert.That(e.Message, Does.Contain("65535"));
        }
    }
}
