using System.IO;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The window's settings go through Unity's serializer (the UserSettings file, presets, undo), so every kind of
    /// field the model has — double, long, enums, flags, nested [Serializable] classes — must survive it. Checked on
    /// a preset, which holds the model the same way as the settings singleton, so the user's own settings file is
    /// never touched by a test.
    /// </summary>
    [TestFixture]
    public class SettingsPersistenceTests
    {
        static DatasetSettings Unusual()
        {
            var s = new DatasetSettings
            {
                Name = "lego_1600",
                OutputFolder = "/data/nerf",
                Scene = "Assets/Scenes/Lego.unity",
                Target = "Props/Lego",
                Distance = 4.25,
                AutoDistance = true,
                AutoDistanceMargin = 1.5,
                Width = 1600,
                Height = 1200,
                Supersampling = 3,
                Background = new BackgroundSettings { Transparent = false, R = 0.25, G = 0.5, B = 1 },
                Seed = (1L << 40) + 7,
                Overwrite = OverwritePolicy.Replace,
                Loaders = TargetLoaders.Nerf | TargetLoaders.Nerfstudio,
            };
            s.Camera.VerticalFovDegrees = 45.5;
            s.Camera.NearClip = 0.03125;
            s.Camera.FarClip = 250;
            s.Camera.CopyFromCamera = "Rig/Main Camera";
            s.Train.Count = 123;
            s.Train.Formation.Kind = FormationKind.Halo;
            s.Train.Formation.ElevationDegrees = 12.5;
            s.Val.Formation.UpperHemisphereOnly = false;
            s.Val.Depth = ExtraOutput.PngAndExr;
            s.Test.Formation.Turns = 3.5;
            s.Test.Normal = ExtraOutput.Exr;
            s.Test.Mask = true;
            return s;
        }

        [Test]
        public void EveryFieldSurvivesUnitysSerializer()
        {
            var original = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            var copy = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            try
            {
                original.StoreSettings(Unusual());
                EditorJsonUtility.FromJsonOverwrite(EditorJsonUtility.ToJson(original), copy);
                Assert.That(DatasetSettingsJson.Write(copy.CopySettings()), Is.EqualTo(DatasetSettingsJson.Write(Unusual())));
                Assert.That(copy.CopySettings().Seed, Is.EqualTo((1L << 40) + 7), "a long beyond int's range");
            }
            finally
            {
                Object.DestroyImmediate(original);
                Object.DestroyImmediate(copy);
            }
        }

        [Test]
        public void NerfSyntheticsFieldOfViewKeepsItsDoublePrecision()
        {
            var original = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            var copy = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            try
            {
                original.StoreSettings(new DatasetSettings());
                EditorJsonUtility.FromJsonOverwrite(EditorJsonUtility.ToJson(original), copy);
                // 0.6911112070083618 rad in degrees needs 16 significant digits; a float would keep about 7.
                Assert.That(copy.CopySettings().Camera.VerticalFovDegrees, Is.EqualTo(CameraSettings.NerfSyntheticVerticalFovDegrees).Within(1e-12));
            }
            finally
            {
                Object.DestroyImmediate(original);
                Object.DestroyImmediate(copy);
            }
        }

        [Test]
        public void AnEditRecordedOnAHiddenSettingsObjectCanBeUndone()
        {
            // The settings singleton is HideAndDontSave (ScriptableSingleton creates it so); undo must still work on it.
            var holder = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            holder.hideFlags = HideFlags.HideAndDontSave;
            try
            {
                holder.StoreSettings(new DatasetSettings());
                Undo.IncrementCurrentGroup();
                Undo.RecordObject(holder, "Edit NeRF dataset settings");
                var edited = holder.CopySettings();
                edited.Train.Count = 7;
                holder.StoreSettings(edited);
                Undo.FlushUndoRecordObjects();
                Undo.PerformUndo();
                Assert.That(holder.CopySettings().Train.Count, Is.EqualTo(100));
            }
            finally
            {
                Undo.ClearUndo(holder);
                Object.DestroyImmediate(holder);
            }
        }

        [Test]
        public void AnUndoOfSomethingElseDoesNotRewriteTheSettingsFile()
        {
            // Undo.undoRedoPerformed fires for every undo in the editor; the window must save only its own changes.
            // Reads the user's settings file's time stamp only: with the fix, nothing writes it.
            var path = Path.Combine(Path.GetDirectoryName(Application.dataPath), "UserSettings", "NeRFDatasetCreator.asset");
            var existed = File.Exists(path);
            var stamp = existed ? File.GetLastWriteTimeUtc(path) : default;
            var window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
            var other = ScriptableObject.CreateInstance<NerfDatasetPreset>();
            other.hideFlags = HideFlags.HideAndDontSave;
            try
            {
                other.StoreSettings(new DatasetSettings());
                Undo.IncrementCurrentGroup();
                Undo.RecordObject(other, "An edit elsewhere");
                other.StoreSettings(new DatasetSettings { Width = 400 });
                Undo.FlushUndoRecordObjects();
                Undo.PerformUndo();
                Assert.That(NerfDatasetCreatorSettings.instance.SaveIfChanged(), Is.False, "the plugin's settings did not change");
                Assert.That(File.Exists(path), Is.EqualTo(existed));
                if (existed) Assert.That(File.GetLastWriteTimeUtc(path), Is.EqualTo(stamp), "the settings file was not rewritten");
            }
            finally
            {
                Undo.ClearUndo(other);
                Object.DestroyImmediate(other);
                window.Close();
            }
        }

        [Test]
        public void TheProjectSettingsAreOneObjectWithSettings()
        {
            Assert.That(NerfDatasetCreatorSettings.instance, Is.SameAs(NerfDatasetCreatorSettings.instance));
            Assert.That(NerfDatasetCreatorSettings.instance.Settings, Is.Not.Null);
        }
    }
}
