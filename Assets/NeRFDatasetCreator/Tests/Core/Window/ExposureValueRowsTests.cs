using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The rows of the Exposure section's list mode.</summary>
    [TestFixture]
    public class ExposureValueRowsTests
    {
        [Test]
        public void AnEntrysProblemsAreUnderItsRow()
        {
            var settings = new DatasetSettings();
            settings.Exposure.Mode = ExposureMode.List;
            settings.Exposure.Values = new List<ViewExposure> { ViewExposure.Identity, new ViewExposure(12, 1, 1, 0.01) };
            var problems = ExposureSettingsValidator.Validate(settings);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "exposure.values[1].ev", "exposure.values[1].whiteBalance[2]" }));
            var fieldProblems = new FieldProblems(problems, null);
            Assert.That(fieldProblems.ErrorsFor(ExposureValueRows.Field(1)), Is.EqualTo(problems));
            Assert.That(fieldProblems.ErrorsFor(ExposureValueRows.Field(0)), Is.Empty);
            Assert.That(fieldProblems.ErrorsFor(ExposureValueRows.ListField, ExposureValueRows.ShownFields(2)), Is.Empty, "nothing is listed twice");
            Assert.That(WindowFields.StepOf(problems[0].Field), Is.EqualTo(WindowStep.Outputs));
        }

        [Test]
        public void AnEmptyListIsReportedBelowTheRows()
        {
            var settings = new DatasetSettings();
            settings.Exposure.Mode = ExposureMode.List;
            var problems = new FieldProblems(ExposureSettingsValidator.Validate(settings), null);
            Assert.That(problems.ErrorsFor(ExposureValueRows.ListField, ExposureValueRows.ShownFields(0)).Select(p => p.Field), Is.EqualTo(new[] { "exposure.values" }));
            Assert.That(problems.ErrorsFor(WindowFields.Exposure, new[] { ExposureValueRows.ListField }), Is.Empty, "not again at the section's end");
        }

        [Test]
        public void ALongListShowsItsFirstRowsAndSaysWhereTheRestIs()
        {
            Assert.That(ExposureValueRows.Shown(3), Is.EqualTo(3));
            Assert.That(ExposureValueRows.Shown(ExposureSettings.MaxValues), Is.EqualTo(ExposureValueRows.MaxRows));
            Assert.That(ExposureValueRows.ShownFields(100).Last(), Is.EqualTo("exposure.values[63]"));
            Assert.That(ExposureValueRows.Summary(3), Is.EqualTo("3 values: view i of a modified split takes value i mod 3."));
            Assert.That(ExposureValueRows.Summary(100), Does.EndWith("The first 64 are shown; edit the rest in a config file (exposure.values)."));
            Assert.That(ExposureValueRows.Summary(0), Does.StartWith("No values yet"));

            // An entry beyond the rows drawn is still reported below them.
            var settings = new DatasetSettings();
            settings.Exposure.Mode = ExposureMode.List;
            settings.Exposure.Values = Enumerable.Repeat(ViewExposure.Identity, 100).ToList();
            settings.Exposure.Values[80] = new ViewExposure(-11, 1, 1, 1);
            var problems = new FieldProblems(ExposureSettingsValidator.Validate(settings), null);
            Assert.That(problems.ErrorsFor(ExposureValueRows.ListField, ExposureValueRows.ShownFields(100)).Select(p => p.Field),
                Is.EqualTo(new[] { "exposure.values[80].ev" }));
        }

        [Test]
        public void AddingCopiesTheLastValue()
        {
            Assert.That(ExposureValueRows.Next(new List<ViewExposure>()), Is.EqualTo(new ViewExposure(0, 1, 1, 1)));
            Assert.That(ExposureValueRows.Next(new[] { new ViewExposure(-1, 1, 1, 1), new ViewExposure(2, 1.3, 1, 0.75) }), Is.EqualTo(new ViewExposure(2, 1.3, 1, 0.75)));
        }
    }
}
