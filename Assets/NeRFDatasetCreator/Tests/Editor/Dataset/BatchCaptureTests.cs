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
    }
}
