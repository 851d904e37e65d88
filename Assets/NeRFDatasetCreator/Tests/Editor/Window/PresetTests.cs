using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    [TestFixture]
    public class PresetTests
    {
        NerfDatasetPreset preset;

        [SetUp]
        public void Create() => preset = ScriptableObject.CreateInstance<NerfDatasetPreset>();

        [TearDown]
        public void Destroy() => Object.DestroyImmediate(preset);

        [Test]
        public void StoringCopiesDeeplySoLaterEditsDoNotReachThePreset()
        {
            var source = new DatasetSettings();
            source.Test.Formation.Turns = 3;
            preset.StoreSettings(source);

            source.Test.Formation.Turns = 9;
            source.Camera.NearClip = 2;
            source.Background.Transparent = false;
            source.Val.Count = 1;

            var stored = preset.CopySettings();
            Assert.That(stored.Test.Formation.Turns, Is.EqualTo(3));
            Assert.That(stored.Camera.NearClip, Is.EqualTo(0.1));
            Assert.That(stored.Background.Transparent, Is.True);
            Assert.That(stored.Val.Count, Is.EqualTo(100));
        }

        [Test]
        public void LoadingGivesAnIndependentCopyEachTime()
        {
            preset.StoreSettings(new DatasetSettings());
            var first = preset.CopySettings();
            first.Train.Formation.TopElevationDegrees = 45;
            first.Camera.FarClip = 7;
            Assert.That(preset.CopySettings().Train.Formation.TopElevationDegrees, Is.EqualTo(90));
            Assert.That(preset.CopySettings().Camera.FarClip, Is.EqualTo(100));
            Assert.That(preset.CopySettings(), Is.Not.SameAs(preset.CopySettings()));
        }

        [Test]
        public void LoadingAPresetKeepsTheWindowsTargetAndScene()
        {
            preset.StoreSettings(new DatasetSettings { Target = "Other/Object", Scene = "Assets/Other.unity", Width = 400, Height = 400 });
            var current = new DatasetSettings { Target = "Props/Lego", Scene = "Assets/Lego.unity" };
            var loaded = preset.ApplyTo(current);
            Assert.That(loaded.Target, Is.EqualTo("Props/Lego"));
            Assert.That(loaded.Scene, Is.EqualTo("Assets/Lego.unity"));
            Assert.That(loaded.Width, Is.EqualTo(400));
        }
    }
}
