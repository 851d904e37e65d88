using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A rendering test's own scene (<see cref="TestScene"/>), opened before each test and closed after it, and the
    /// assets a test makes in code (meshes, materials, textures), destroyed after it: they live outside any scene.
    /// Ignores the test where nothing can be rendered.
    /// </summary>
    public abstract class GpuSceneFixture
    {
        readonly List<Object> _owned = new List<Object>();

        protected Scene TestSceneOfThisTest { get; private set; }

        [SetUp]
        public void OpenTestScene()
        {
            TestScene.RequireRendering();
            TestSceneOfThisTest = TestScene.Open();
        }

        [TearDown]
        public void CloseTestScene()
        {
            TestScene.Close(TestSceneOfThisTest);
            foreach (var owned in _owned)
                if (owned != null) Object.DestroyImmediate(owned);
            _owned.Clear();
        }

        /// <summary>Destroys <paramref name="asset"/> after the test; returns it.</summary>
        protected T Own<T>(T asset) where T : Object
        {
            _owned.Add(asset);
            return asset;
        }
    }
}
