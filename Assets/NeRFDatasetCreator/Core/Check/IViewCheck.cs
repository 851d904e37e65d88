using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>A check that looks at one view at a time; <see cref="DatasetCheck"/> feeds it every decoded view, then asks for its result.</summary>
    public interface IViewCheck
    {
        string Name { get; }

        void View(CheckView view, CheckImages images, List<DatasetProblem> problems);

        DatasetCheckResult Finish();
    }
}
