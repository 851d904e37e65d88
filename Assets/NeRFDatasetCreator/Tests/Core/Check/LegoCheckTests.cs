using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The real nerf_synthetic lego cameras (transforms_train.json: poses and camera_angle_x only, no depth, normals or
    /// masks, as nerf_synthetic's train split) with analytic RGBA images rendered at its poses (<see cref="AnalyticLego"/>):
    /// the check passes, skipping what needs the missing files, one line each.
    /// </summary>
    [TestFixture]
    public class LegoCheckTests
    {
        [Test]
        public void LegoPassesWithItsSkips()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("lego");
                AnalyticLego.Write(folder);

                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
                TestContext.WriteLine(text);
                Assert.That(report.Failed, Is.False, text);
                Assert.That(report.ViewsChecked, Is.EqualTo(100));
                Assert.That(report.Results.Single(r => r.Name == "alpha vs mask").Status, Is.EqualTo(DatasetCheckStatus.Passed), text);
                foreach (var name in new[] { "depth vs mask", "depth vs normals", "multi-view geometry", "point cloud vs masks", "colour vs geometry", "geometry pack vs depth" })
                {
                    var result = report.Results.Single(r => r.Name == name);
                    Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Skipped), name);
                    Assert.That(result.SummaryLine, Does.StartWith(name + ": skipped ("), name);
                }
            }
        }
    }
}
