using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The sample scene is hand-written YAML: its objects must reference each other consistently, and it must not hold
    /// components of a built-in module the project does not enable (Unity drops a disabled module's types).
    /// </summary>
    [TestFixture]
    public class SampleSceneTests
    {
        static readonly Regex Header = new Regex(@"^--- !u!(\d+) &(-?\d+)", RegexOptions.Multiline);

        /// <summary>Each YAML document of the scene: (class ID, file ID, text).</summary>
        static List<(int ClassId, string FileId, string Text)> Documents()
        {
            var text = File.ReadAllText(RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", "NeRFSample.unity"));
            var matches = Header.Matches(text).Cast<Match>().ToList();
            var documents = new List<(int, string, string)>();
            for (var i = 0; i < matches.Count; i++)
            {
                var end = i + 1 < matches.Count ? matches[i + 1].Index : text.Length;
                documents.Add((int.Parse(matches[i].Groups[1].Value), matches[i].Groups[2].Value, text.Substring(matches[i].Index, end - matches[i].Index)));
            }
            return documents;
        }

        [Test]
        public void EveryGameObjectListsExactlyTheComponentsThatNameIt()
        {
            var documents = Documents();
            Assert.That(documents.Count(d => d.ClassId == 1), Is.GreaterThan(0));
            foreach (var go in documents.Where(d => d.ClassId == 1))
            {
                var listed = Regex.Matches(go.Text, @"- component: \{fileID: (\d+)\}").Cast<Match>().Select(m => m.Groups[1].Value).ToList();
                var naming = documents.Where(d => Regex.IsMatch(d.Text, @"^  m_GameObject: \{fileID: " + go.FileId + @"\}", RegexOptions.Multiline))
                    .Select(d => d.FileId).ToList();
                Assert.That(listed, Is.EquivalentTo(naming), "GameObject &" + go.FileId);
            }
        }

        [Test]
        public void NoAudioComponentWithoutTheAudioModule()
        {
            var manifest = File.ReadAllText(RepositoryPaths.Combine("Packages", "manifest.json"));
            if (manifest.Contains("\"com.unity.modules.audio\"")) Assert.Ignore("the project enables the audio module");
            // Class IDs 81 AudioListener, 82 AudioSource (Unity Manual, "YAML class ID reference").
            Assert.That(Documents().Where(d => d.ClassId == 81 || d.ClassId == 82).Select(d => d.FileId), Is.Empty);
        }
    }
}
