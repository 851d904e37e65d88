using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "relighting" section of the settings (issue 38): the same views under K more lighting conditions
    /// (<see cref="LightingCondition"/>), described in lights.json (Documentation~/relighting.md). The plain
    /// <c>r_&lt;i&gt;.png</c> keep the scene's own lighting. Off by default, and then nothing about the dataset changes.
    /// </summary>
    [Serializable]
    public sealed class RelightingSettings
    {
        /// <summary>On when the section is given (and not <c>"enabled": false</c>).</summary>
        public bool On;

        public List<LightingCondition> Conditions = new List<LightingCondition>();

        public bool Enabled => On && Conditions != null && Conditions.Count > 0;

        public RelightingSettings Clone()
        {
            var copy = (RelightingSettings)MemberwiseClone();
            copy.Conditions = Conditions?.Select(c => c?.Clone()).ToList();
            return copy;
        }
    }
}
