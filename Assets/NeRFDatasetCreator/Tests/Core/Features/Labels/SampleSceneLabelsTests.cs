using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The worked example of Documentation~/labels.md: the sample scene's NeRFTarget (scene root 2 of
    /// Assets/Samples/NeRFSample/NeRFSample.unity) with its five children, all Untagged on the Default layer and no
    /// prefabs, labelled with the page's config. The numbers here are the page's; the colours are LabelColours' formula worked by hand (id 1: hue 0.382 turn, saturation 0.75, value 1 → (0.25, 1, 0.469) → #40ff78).
    /// </summary>
    public class SampleSceneLabelsTests
    {
        static SceneObjectInfo[] SampleTarget()
        {
            var target = new SceneNode("NeRFTarget", 2, "Untagged", "Default");
            return new[] { "Base", "Tower", "Head", "Arm", "Pointer" }
                .Select((name, i) => new SceneObjectInfo(new[] { target, new SceneNode(name, i, "Untagged", "Default") }, 1)).ToArray();
        }

        [Test]
        public void TheDocumentedConfigGivesTheDocumentedIds()
        {
            var settings = DatasetSettingsJson.Read(@"{ ""labels"": {
                ""instances"": ""prefab"", ""classFrom"": ""name"",
                ""classes"": [ { ""match"": ""Base"", ""class"": ""ground"" }, { ""match"": ""Head"", ""class"": ""ball"" }, { ""match"": ""*"", ""class"": ""structure"" } ] } }").Settings;
            Assert.That(SettingsValidator.Validate(settings), Is.Empty);
            var table = LabelTable.Build(settings.Labels, SampleTarget().Reverse());
            Assert.That(table.Instances.Select(i => i.Id + " " + i.Path + " " + i.ClassId + " " + i.ClassName), Is.EqualTo(new[]
            {
                "1 NeRFTarget/Base 1 ground", "2 NeRFTarget/Tower 3 structure", "3 NeRFTarget/Head 2 ball", "4 NeRFTarget/Arm 3 structure", "5 NeRFTarget/Pointer 3 structure",
            }));
            var json = JObject.Parse(LabelsJson.Write(table));
            Assert.That(json["classes"].Select(c => (string)c["name"] + " " + (string)c["colour"]), Is.EqualTo(new[] { "ground #40ff78", "ball #ba59ff", "structure #ecd323" }));
            Assert.That(json["instances"].Select(i => (string)i["colour"]), Is.EqualTo(new[] { "#40ff78", "#ba59ff", "#ecd323", "#3bceec", "#ec53a6" }));
        }

        [Test]
        public void WithoutRulesEveryTagIsAClass()
        {
            var table = LabelTable.Build(new LabelSettings { Enabled = true }, SampleTarget());
            Assert.That(table.Classes.Select(c => c.Name), Is.EqualTo(new[] { "Untagged" }));
            Assert.That(table.Instances.Select(i => i.ClassId).Distinct(), Is.EqualTo(new[] { 1 }));
        }
    }
}
