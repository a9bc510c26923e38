// SPDX-License-Identifier: Apache-2.0
// Enteron's frame and Unity's. Enteron is right-handed with z up (gravity along -z, SI
// units); Unity is left-handed with y up. Swapping y and z maps one onto the other: x stays,
// Unity's up is Enteron's z, 1 Unity unit is 1 m. The swap is a mirror (its own inverse),
// so it also turns right-handed rotations into left-handed ones: a rotation R becomes
// M R M, the same angle about the mirrored axis taken the other way round, which for a
// quaternion (w, v) is (w, -M v). A triangle counter-clockwise seen from outside in Enteron
// is clockwise seen from outside in Unity, which is Unity's front face: indices need no change.
using UnityEngine;

namespace Enteron.Unity
{
    /// <summary>Conversions between Enteron's frame (right-handed, z up) and Unity's (left-handed, y up).</summary>
    public static class EnteronSpace
    {
        /// <summary>A Unity point or vector (in the scene component's frame) in Enteron's frame.</summary>
        public static Vec3 ToEnteron(Vector3 v)
        {
            return new Vec3(v.x, v.z, v.y);
        }

        /// <summary>An Enteron point or vector in Unity's frame (of the scene component).</summary>
        public static Vector3 ToUnity(Vec3 v)
        {
            return new Vector3((float)v.X, (float)v.Z, (float)v.Y);
        }

        /// <summary>A Unity rotation in Enteron's frame: (w, x, y, z) becomes (w, -x, -z, -y).</summary>
        public static Quat ToEnteron(Quaternion q)
        {
            return new Quat(q.w, -q.x, -q.z, -q.y);
        }

        /// <summary>An Enteron rotation in Unity's frame.</summary>
        public static Quaternion ToUnity(Quat q)
        {
            return new Quaternion((float)-q.X, (float)-q.Z, (float)-q.Y, (float)q.W);
        }

        /// <summary>
        /// A 3 x 3 matrix of Enteron's frame (a tool's stiffness dF/dx) in Unity's: M K M. In
        /// the upper-left 3 x 3 of the result, the rest zero: apply it with MultiplyVector.
        /// </summary>
        public static Matrix4x4 ToUnity(Matrix3 k)
        {
            var m = new Matrix4x4();
            m.m00 = (float)k.M00; m.m01 = (float)k.M02; m.m02 = (float)k.M01;
            m.m10 = (float)k.M20; m.m11 = (float)k.M22; m.m12 = (float)k.M21;
            m.m20 = (float)k.M10; m.m21 = (float)k.M12; m.m22 = (float)k.M11;
            return m;
        }
    }
}
