using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The summary lines of check and validate: how many checks ran, and problem lists capped with a count (issue 33).</summary>
    [TestFixture]
    public class CheckOutputTests
    {
        [Test]
        public void OkSaysHowManyChecksRanAndNamesTheSkippedOnes()
        {
            var report = new DatasetCheckReport("d");
            report.Add(new DatasetCheckResult("dataset", DatasetCheckStatus.Passed, "7 views", null, null));
            report.Add(new DatasetCheckResult("alpha vs mask", DatasetCheckStatus.Passed, "0.1 %", "1 %", null));
            report.Add(DatasetCheckResult.Skip("depth vs mask", "no depth"));
            report.Add(DatasetCheckResult.Skip("motion blur", "no view is motion-blurred"));
            Assert.That(CheckVerdict.Passed(report), Is.EqualTo("OK (2 of 4 checks ran; 2 skipped: depth vs mask, motion blur)"));

            var all = new DatasetCheckReport("d");
            all.Add(new DatasetCheckResult("dataset", DatasetCheckStatus.Passed, "7 views", null, null));
            Assert.That(CheckVerdict.Passed(all), Is.EqualTo("OK (1 of 1 checks ran)"));
        }

        [Test]
        public void ProblemListsShowTwentyPerCheckThenCountTheRest()
        {
            var problems = Enumerable.Range(0, 25).Select(i => new DatasetProblem("depth vs mask", "./train/r_" + i + ".png", i, "differs"))
                .Concat(Enumerable.Range(0, 3).Select(i => new DatasetProblem("alpha vs mask", "./val/r_" + i + ".png", i, "differs")))
                .Concat(new[] { new DatasetProblem("depth vs mask", "./test/r_0.png", 0, "differs") })
                .ToList();
            var lines = ProblemList.Lines(problems, "problem: ", "--json FILE lists every one").ToList();
            // 20 of the 26 depth problems, the 3 alpha problems, then one line for the 6 depth problems not shown.
            Assert.That(lines, Has.Count.EqualTo(20 + 3 + 1));
            Assert.That(lines[0], Is.EqualTo("problem: ./train/r_0.png frame 0 [depth vs mask]: differs"));
            Assert.That(lines[19], Is.EqualTo("problem: ./train/r_19.png frame 19 [depth vs mask]: differs"));
            Assert.That(lines[20], Is.EqualTo("problem: ./val/r_0.png frame 0 [alpha vs mask]: differs"));
            Assert.That(lines.Last(), Is.EqualTo("problem: … and 6 more [depth vs mask] like these (26 in all; --json FILE lists every one)."));
        }

        [Test]
        public void ShortListsAndStructuralProblemsAreCappedTheSameWay()
        {
            var few = Enumerable.Range(0, 20).Select(i => DatasetProblem.Structure("transforms_train.json", i, "./train/r_" + i, "image is missing")).ToList();
            Assert.That(ProblemList.Lines(few, "problem: ", null).Count(), Is.EqualTo(20), "twenty are all shown");
            few.Add(DatasetProblem.Structure("transforms_train.json", 20, "./train/r_20", "image is missing"));
            Assert.That(ProblemList.Lines(few, "problem: ", null).Last(), Is.EqualTo("problem: … and 1 more like it (21 in all)."));
        }
    }
}
