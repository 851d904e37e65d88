using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Batch-mode refusals that need no rendering: each returns its exit code before touching the scene.</summary>
    [TestFixture]
    public class BatchCaptureTests
    {
        [Test]
        public void AMissingConfigArgumentIsInvalidInput()
        {
            LogAssert.Expect(LogType.Error, new Regex("nothing was captured: the command line is invalid.*-nerfConfig", RegexOptions.Singleline));
            Assert.That(BatchCapture.Execute(new[] { "Unity", "-batchmode", "-nerfOut", "out" }), Is.EqualTo(BatchCapture.InvalidInput));
        }

        [Test]
        public void AConfigFileThatDoesNotExistIsInvalidInputOrNoGraphicsDevice()
        {
            var noDevice = SystemInfo.graphicsDeviceType == GraphicsDeviceType.Null;
            // Without a graphics device that check comes first: nothing could be rendered anyway.
            LogAssert.Expect(LogType.Error, new Regex(noDevice ? "-nographics" : "the config file is missing"));
            var code = BatchCapture.Execute(new[] { "-nerfConfig", "Assets/no-such-config-" + System.Guid.NewGuid().ToString("N") + ".json" });
            Assert.That(code, Is.EqualTo(noDevice ? BatchCapture.NoGraphicsDevice : BatchCapture.InvalidInput));
        }

        // batch-mode.md's table: a missing scene or target is invalid input (2), like a bad config, not a failure (1).
        [Test]
        public void AMissingSceneIsInvalidInput()
        {
            var settings = new DatasetSettings { Scene = "Assets/no-such-scene-" + System.Guid.NewGuid().ToString("N") + ".unity", Target = "Anything" };
            Assert.That(ExecuteWith(settings, "the scene is missing"), Is.EqualTo(BatchCapture.InvalidInput));
        }

        [Test]
        public void AMissingTargetIsInvalidInput()
        {
            var settings = new DatasetSettings { Scene = "", Target = "No object is called this " + System.Guid.NewGuid().ToString("N") };
            Assert.That(ExecuteWith(settings, "the target is missing"), Is.EqualTo(BatchCapture.InvalidInput));
        }

        /// <summary>Runs Execute with <paramref name="settings"/> in a temporary config file, expecting one refusal.</summary>
        static int ExecuteWith(DatasetSettings settings, string refusal)
        {
            if (SystemInfo.graphicsDeviceType == GraphicsDeviceType.Null) Assert.Ignore("no graphics device: Execute stops at that check first");
            var config = Path.Combine(Path.GetTempPath(), "nerf-batch-" + System.Guid.NewGuid().ToString("N") + ".json");
            File.WriteAllText(config, DatasetSettingsJson.Write(settings));
            try
            {
                LogAssert.Expect(LogType.Error, new Regex("nothing was captured: " + refusal));
                return BatchCapture.Execute(new[] { "-nerfConfig", config });
            }
            finally
            {
                File.Delete(config);
            }
        }
    }
}
