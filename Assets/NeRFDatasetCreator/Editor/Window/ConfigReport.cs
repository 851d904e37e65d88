using System;
using System.Collections.Generic;
using System.Linq;
using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>What the last preset or config action said: an error (a config that could not be read, with line and column), warnings, or a note.</summary>
    [Serializable]
    sealed class ConfigReport
    {
        public string Message = "";
        public MessageType Type = MessageType.None;
        public List<string> Warnings = new List<string>();

        public void Set(string message, MessageType type, IEnumerable<ValidationProblem> warnings = null)
        {
            Message = message ?? "";
            Type = type;
            Warnings = (warnings ?? Enumerable.Empty<ValidationProblem>()).Select(WindowText.ProblemWithField).ToList();
        }

        public void Draw()
        {
            if (Message.Length > 0) EditorGUILayout.HelpBox(Message, Type);
            foreach (var warning in Warnings) EditorGUILayout.HelpBox(warning, MessageType.Warning);
        }
    }
}
