using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>What a conversion wrote and what the user should know (warnings never stop a conversion).</summary>
    public sealed class ConversionResult
    {
        public ConversionResult(string outputDirectory, string mainFile, IReadOnlyList<string> writtenFiles, IReadOnlyList<ValidationProblem> warnings,
            IReadOnlyList<string> trainCommands = null, string fileReferences = null)
        {
            FileReferences = fileReferences;
            TrainCommands = trainCommands ?? new string[0];
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

        /// <summary>Training commands worked out for this dataset (nerfstudio: one per model family); empty when the format has one fixed command.</summary>
        public IReadOnlyList<string> TrainCommands { get; }

        /// <summary>What the export depends on: whether it holds the files it names or names the dataset's (<see cref="ExportFileReferences.Describe"/>); null when it writes its own.</summary>
        public string FileReferences { get; }
    }
}
