using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Switching to a relighting condition (issue 38) changes the lighting as the condition says, and switching back
    /// restores every RenderSettings field it touched and every light's enabled state exactly, also when the switch
    /// fails half-way. Runs on the test's own active scene (RenderSettings address it), with a small equirect EXR asset.
    /// </summary>
    [TestFixture]
    public class LightingSwitchTests
    {
        UnityEngine.SceneManagement.Scene _scene;
        string _folder;
        Light _on, _off;
        Material _userSky;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _folder = "Assets/nerf-relight-" + Guid.NewGuid().ToString("N");
            AssetDatabase.CreateFolder("Assets", _folder.Substring("Assets/".Length));
            _on = new GameObject("Key", typeof(Light)).GetComponent<Light>();
            _off = new GameObject("Fill", typeof(Light)).GetComponent<Light>();
            _off.enabled = false;
            // A user's lighting unlike anything a condition sets.
            _userSky = new Material(Shader.Find("Skybox/Procedural")) { hideFlags = HideFlags.HideAndDontSave };
            RenderSettings.skybox = _userSky;
            RenderSettings.ambientMode = AmbientMode.Trilight;
            RenderSettings.ambientSkyColor = new Color(0.3f, 0.2f, 0.1f);
            RenderSettings.ambientEquatorColor = new Color(0.1f, 0.3f, 0.2f);
            RenderSettings.ambientGroundColor = new Color(0.2f, 0.1f, 0.3f);
            RenderSettings.ambientIntensity = 0.7f;
            RenderSettings.reflectionIntensity = 0.6f;
            RenderSettings.defaultReflectionMode = DefaultReflectionMode.Skybox;
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_folder != null) AssetDatabase.DeleteAsset(_folder);
            if (_userSky != null) Object.DestroyImmediate(_userSky);
        }

        Light[] Lights => new[] { _on, _off };

        /// <summary>A 16 × 8 float equirect EXR imported as a 2D texture; its project path.</summary>
        string EquirectAsset()
        {
            var texture = new Texture2D(16, 8, TextureFormat.RGBAFloat, false, true);
            var pixels = new Color[16 * 8];
            for (var i = 0; i < pixels.Length; i++) pixels[i] = new Color(2f, 1f, 0.5f, 1f);
            texture.SetPixels(pixels);
            var path = _folder + "/sky.exr";
            File.WriteAllBytes(path, texture.EncodeToEXR(Texture2D.EXRFlags.OutputAsFloat));
            Object.DestroyImmediate(texture);
            AssetDatabase.ImportAsset(path, ImportAssetOptions.ForceSynchronousImport);
            return path;
        }

        [Test]
        public void AnEnvironmentConditionAndBackRestoresEverySettingAndLight()
        {
            var before = new LightingState(Lights);
            var sunset = new LightingCondition { Name = "sunset", Kind = LightingKind.Environment, File = EquirectAsset(), Rotations = new double[] { 90 }, Intensity = 2 };
            var render = RelightingInUnity.Resolve(new RelightingSettings { On = true, Conditions = new List<LightingCondition> { sunset } }, SceneNormalisation.Identity)[0];
            using (LightingSwitch.Apply(render, Lights, null, 10f))
            {
                Assert.That(RenderSettings.skybox, Is.Not.SameAs(_userSky));
                Assert.That(RenderSettings.skybox.shader.name, Is.EqualTo("Skybox/Panoramic"));
                Assert.That(RenderSettings.skybox.GetFloat("_Rotation"), Is.EqualTo(90f));
                Assert.That(RenderSettings.ambientMode, Is.EqualTo(AmbientMode.Skybox));
                Assert.That(_on.enabled, Is.False, "every other light is off");
            }
            var after = new LightingState(Lights);
            Assert.That(before.FirstDifference(after), Is.Null);
            Assert.That(RenderSettings.skybox, Is.SameAs(_userSky));
            Assert.That(RenderSettings.ambientMode, Is.EqualTo(AmbientMode.Trilight));
            Assert.That(RenderSettings.ambientIntensity, Is.EqualTo(0.7f));
            Assert.That(RenderSettings.reflectionIntensity, Is.EqualTo(0.6f));
            Assert.That(_on.enabled, Is.True);
            Assert.That(_off.enabled, Is.False);
        }

        [Test]
        public void APointLightConditionAndBackRestoresEverythingAndRemovesItsLight()
        {
            var before = new LightingState(Lights);
            var olat = new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new double[] { 0, -3, 3 }, Intensity = 20 };
            var render = RelightingInUnity.Resolve(new RelightingSettings { On = true, Conditions = new List<LightingCondition> { olat } }, SceneNormalisation.Identity)[0];
            var parent = new GameObject("Capture root").transform;
            using (LightingSwitch.Apply(render, Lights, parent, 10f))
            {
                var added = parent.GetComponentsInChildren<Light>(true);
                Assert.That(added, Has.Length.EqualTo(1));
                // Output (0, −3, 3) is Unity (0, 3, −3) (BlenderConvention, identity normalisation).
                Assert.That(Vector3.Distance(added[0].transform.position, new Vector3(0, 3, -3)), Is.LessThan(1e-5f));
                Assert.That(added[0].type, Is.EqualTo(LightType.Point));
                Assert.That(added[0].intensity, Is.EqualTo(20f));
                Assert.That(RenderSettings.ambientProbe, Is.EqualTo(new SphericalHarmonicsL2()), "no ambient");
                Assert.That(RenderSettings.reflectionIntensity, Is.EqualTo(0f));
                Assert.That(_on.enabled, Is.False);
            }
            Assert.That(parent.GetComponentsInChildren<Light>(true), Is.Empty, "the condition's light is gone");
            Assert.That(before.FirstDifference(new LightingState(Lights)), Is.Null);
            Object.DestroyImmediate(parent.gameObject);
        }

        [Test]
        public void ASwitchThatFailsRestoresEverythingBeforeItThrows()
        {
            var before = new LightingState(Lights);
            var broken = new LightingCondition { Name = "gone", Kind = LightingKind.Environment, File = _folder + "/missing.exr" };
            var missing = RelightingInUnity.Resolve(new RelightingSettings { On = true, Conditions = new List<LightingCondition> { broken } }, SceneNormalisation.Identity)[0];
            var error = Assert.Throws<CaptureException>(() => LightingSwitch.Apply(missing, Lights, null, 10f));
            Assert.That(error.Message, Does.Contain("missing.exr").And.Contain("gone_000"));
            Assert.That(before.FirstDifference(new LightingState(Lights)), Is.Null, "the lights were switched off before the map was read; they are back");
            Assert.That(_on.enabled, Is.True);
        }
    }
}
