// SPDX-License-Identifier: Apache-2.0
// The small fixed arrays of the C API as blittable structs: a double[3] is a Vec3, a
// quaternion double[4] (w x y z) a Quat, a row-major double[9] a Matrix3. Same memory
// layout as the C arrays, so a struct field of these types sits where the C array does.
using System;
using System.Globalization;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>Three doubles x, y, z: a point (m), a force (N), a velocity... (a C double[3]).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3 : IEquatable<Vec3>
    {
        /// <summary>x</summary>
        public double X;
        /// <summary>y</summary>
        public double Y;
        /// <summary>z</summary>
        public double Z;

        /// <summary>(x, y, z)</summary>
        public Vec3(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>(0, 0, 0)</summary>
        public static Vec3 Zero
        {
            get { return new Vec3(0, 0, 0); }
        }

        /// <summary>The Euclidean norm.</summary>
        public double Length
        {
            get { return Math.Sqrt(X * X + Y * Y + Z * Z); }
        }

        /// <summary>a + b</summary>
        public static Vec3 operator +(Vec3 a, Vec3 b)
        {
            return new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        }

        /// <summary>a - b</summary>
        public static Vec3 operator -(Vec3 a, Vec3 b)
        {
            return new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        }

        /// <summary>-a</summary>
        public static Vec3 operator -(Vec3 a)
        {
            return new Vec3(-a.X, -a.Y, -a.Z);
        }

        /// <summary>s a</summary>
        public static Vec3 operator *(double s, Vec3 a)
        {
            return new Vec3(s * a.X, s * a.Y, s * a.Z);
        }

        /// <summary>The dot product.</summary>
        public static double Dot(Vec3 a, Vec3 b)
        {
            return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        }

        /// <summary>Bit for bit the same numbers (NaN equals NaN of the same bits).</summary>
        public bool Equals(Vec3 other)
        {
            return X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);
        }

        /// <summary>See <see cref="Equals(Vec3)"/>.</summary>
        public override bool Equals(object obj)
        {
            return obj is Vec3 && Equals((Vec3)obj);
        }

        /// <summary>A hash of the three numbers.</summary>
        public override int GetHashCode()
        {
            return X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919);
        }

        /// <summary>"(x, y, z)" with invariant culture.</summary>
        public override string ToString()
        {
            return string.Format(CultureInfo.InvariantCulture, "({0}, {1}, {2})", X, Y, Z);
        }
    }

    /// <summary>A rotation as a quaternion w, x, y, z (a C double[4] orientation_wxyz).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Quat
    {
        /// <summary>the scalar part</summary>
        public double W;
        /// <summary>x</summary>
        public double X;
        /// <summary>y</summary>
        public double Y;
        /// <summary>z</summary>
        public double Z;

        /// <summary>(w, x, y, z); the library normalises a non-unit quaternion.</summary>
        public Quat(double w, double x, double y, double z)
        {
            W = w;
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>(1, 0, 0, 0): no rotation. A tool with it points straight down, its shaft rising along +z.</summary>
        public static Quat Identity
        {
            get { return new Quat(1, 0, 0, 0); }
        }

        /// <summary>"(w, x, y, z)" with invariant culture.</summary>
        public override string ToString()
        {
            return string.Format(CultureInfo.InvariantCulture, "({0}, {1}, {2}, {3})", W, X, Y, Z);
        }
    }

    /// <summary>A 3 x 3 matrix, row-major (a C double[9]): M01 is row 0, column 1.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Matrix3
    {
        /// <summary>row 0, column 0</summary>
        public double M00;
        /// <summary>row 0, column 1</summary>
        public double M01;
        /// <summary>row 0, column 2</summary>
        public double M02;
        /// <summary>row 1, column 0</summary>
        public double M10;
        /// <summary>row 1, column 1</summary>
        public double M11;
        /// <summary>row 1, column 2</summary>
        public double M12;
        /// <summary>row 2, column 0</summary>
        public double M20;
        /// <summary>row 2, column 1</summary>
        public double M21;
        /// <summary>row 2, column 2</summary>
        public double M22;

        /// <summary>The entry at (row, column), each 0 to 2.</summary>
        public double this[int row, int column]
        {
            get
            {
                if ((uint)row > 2 || (uint)column > 2)
                    throw new ArgumentOutOfRangeException(row > 2 || row < 0 ? "row" : "column", "must be 0, 1 or 2");
                unsafe
                {
                    fixed (double* first = &M00) return first[3 * row + column];
                }
            }
        }

        /// <summary>M v</summary>
        public static Vec3 operator *(Matrix3 m, Vec3 v)
        {
            return new Vec3(m.M00 * v.X + m.M01 * v.Y + m.M02 * v.Z,
                            m.M10 * v.X + m.M11 * v.Y + m.M12 * v.Z,
                            m.M20 * v.X + m.M21 * v.Y + m.M22 * v.Z);
        }
    }
}
