package raytracer.reference;

/**
 * The n-point Gauss-Legendre rule on [0, 1]: exact for polynomials of degree up to 2n - 1, and for
 * smooth integrands its error falls faster than any power of 1/n (Press et al., Numerical Recipes,
 * section 4.6). Nodes are the roots of the Legendre polynomial P_n, found by Newton's method.
 */
final class GaussLegendre {
    private final double[] nodes;
    private final double[] weights;

    GaussLegendre(int n) {
        if (n < 1 || n > 256) {
            throw new IllegalArgumentException("Gauss-Legendre order must be 1 to 256, got " + n);
        }
        nodes = new double[n];
        weights = new double[n];
        for (int i = 0; i < (n + 1) / 2; i++) {
            // Tricomi's first guess for the i-th root, refined by Newton's method on P_n
            double x = Math.cos(Math.PI * (i + 0.75) / (n + 0.5));
            double derivative = 0;
            for (int iteration = 0; iteration < 100; iteration++) {
                double p0 = 1;
                double p1 = x;
                for (int k = 2; k <= n; k++) { // Bonnet's recursion: k P_k = (2k - 1) x P_{k-1} - (k - 1) P_{k-2}
                    double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (x * p1 - p0) / (x * x - 1);
                double step = p1 / derivative;
                x -= step;
                if (Math.abs(step) < 1e-16) {
                    break;
                }
            }
            // weight on [-1, 1]: 2 / ((1 - x^2) P_n'(x)^2); halved on [0, 1]
            double w = 1 / ((1 - x * x) * derivative * derivative);
            nodes[i] = (1 - x) / 2;
            nodes[n - 1 - i] = (1 + x) / 2;
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
    }

    int order() {
        return nodes.length;
    }

    double node(int i) {
        return nodes[i];
    }

    double weight(int i) {
        return weights[i];
    }
}
