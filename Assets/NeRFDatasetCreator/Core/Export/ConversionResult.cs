using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>What a conversion wrote and what the user should know (warnings never stop a conversion).</summary>
    public sealed class ConversionResult
    {
        public ConversionResult(string outputDirectory, string mainFile, IReadOnlyList<string> writtenFiles, IReadOnlyList<ValidationProblem> warnings)
        {
            OutputDirectory = outputDirectory;
            MainFile = mainFile;
            WrittenFiles = writtenFiles;
            Warnings = warnings;
        }

        public string OutputDirectory { get; }

        /// <summary>The file to hand to the trainer (transforms.json) or the COLMAP source folder.</summary>
        public string MainFile { get; }

        public IReadOnlyList<string> WrittenFiles { get; }
        public IReadOnlyList<ValidationProblem> Warnings { get; }
    }
}
