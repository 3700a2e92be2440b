"""Checks behind models/entropic/derivations.md (pure python + sympy, runs in ~1 s).
Finite-difference checks of the five pair forces against -dU/dx, of theta_a = dE/dS_a,
of the printed (37b), of the dissipative/hyperbolic energy balances, and sympy checks of App. C."""
import math, random
random.seed(3)
gam, cV, h = 1.4, 1.0, 0.75
C2 = 7/math.pi                                   # 2D Wendland quintic, support radius h
def W(r):  q=r/h; return C2/h**2*(1-q)**4*(1+4*q) if q<1 else 0.0
def Wp(r): q=r/h; return -20*C2/h**3*q*(1-q)**3 if q<1 else 0.0
def eps(rho,s): return rho**gam/(gam-1)*math.exp(s/(rho*cV))        # (88)
def T_(rho,s): return eps(rho,s)/(rho*cV)                           # (89b)
def p_(rho,s): return (gam-1)*eps(rho,s)                            # (89a)
def mu_(rho,s): return gam*eps(rho,s)/rho - eps(rho,s)*s/(rho**2*cV) # (89c)
X=[[0.3*i+random.uniform(-.03,.03),0.3*j+random.uniform(-.03,.03)] for i in range(3) for j in range(3)]
N=len(X); m=[random.uniform(.8,1.2) for _ in range(N)]; S=[random.uniform(.3,.6) for _ in range(N)]
def dist(X,a,b): return math.hypot(X[a][0]-X[b][0],X[a][1]-X[b][1])
def solve(A,b):
    n=len(b); M=[row[:]+[b[i]] for i,row in enumerate(A)]
    for i in range(n):
        piv=max(range(i,n),key=lambda r:abs(M[r][i])); M[i],M[piv]=M[piv],M[i]
        for r in range(n):
            if r!=i:
                f=M[r][i]/M[i][i]
                for c in range(i,n+1): M[r][c]-=f*M[i][c]
    return [M[i][n]/M[i][i] for i in range(n)]
def state(X,S,kind):
    Wm=[[W(dist(X,a,b)) for b in range(N)] for a in range(N)]   # includes self term W(0)
    if kind=='mass':
        rho=[sum(m[b]*Wm[a][b] for b in range(N)) for a in range(N)]; V=[m[a]/rho[a] for a in range(N)]; s=[S[a]/V[a] for a in range(N)]
    elif kind=='entropic':
        s=[sum(S[b]*Wm[a][b] for b in range(N)) for a in range(N)]; V=[S[a]/s[a] for a in range(N)]; rho=[m[a]/V[a] for a in range(N)]
    elif kind=='direct':
        V=[1/sum(Wm[a]) for a in range(N)]; rho=[m[a]/V[a] for a in range(N)]; s=[S[a]/V[a] for a in range(N)]
    elif kind=='implicit':
        V=solve(Wm,[1.0]*N); rho=[m[a]/V[a] for a in range(N)]; s=[S[a]/V[a] for a in range(N)]
    elif kind=='mixed':
        rho=[sum(m[b]*Wm[a][b] for b in range(N)) for a in range(N)]; s=[sum(S[b]*Wm[a][b] for b in range(N)) for a in range(N)]
        V=[m[a]/rho[a] for a in range(N)]
    return Wm,rho,s,V
def U(X,S,kind):
    Wm,rho,s,V=state(X,S,kind); return sum(V[a]*eps(rho[a],s[a]) for a in range(N))
def Phi_all(X,S,kind,printed37b=False):
    Wm,rho,s,V=state(X,S,kind); p=[p_(rho[a],s[a]) for a in range(N)]; T=[T_(rho[a],s[a]) for a in range(N)]
    y=solve(Wm,p) if kind=='implicit' else None
    def Phi(a,b):
        if kind=='mass': return m[a]*m[b]*(p[a]/rho[a]**2+p[b]/rho[b]**2)
        if kind=='entropic':
            if not printed37b: return S[a]*S[b]*(p[a]/s[a]**2+p[b]/s[b]**2)
            Er=[V[c]*mu_(rho[c],s[c]) for c in range(N)]; Es=[-S[c]*eps(rho[c],s[c])/s[c]**2+V[c]*T[c] for c in range(N)]
            return S[a]*S[b]*(m[a]/S[a]**2*Er[a]+m[b]/S[b]*Er[b]+Es[a]/S[a]+Es[b]/S[b])
        if kind=='direct': return p[a]*V[a]**2+p[b]*V[b]**2
        if kind=='implicit': return y[a]*V[b]+y[b]*V[a]
        A=[m[c]*(p[c]-s[c]*T[c])/rho[c]**2 for c in range(N)]; B=[m[c]*T[c]/rho[c] for c in range(N)]
        return m[b]*A[a]+m[a]*A[b]+S[b]*B[a]+S[a]*B[b]
    return Phi
def force(X,S,kind,**kw):
    Phi=Phi_all(X,S,kind,**kw); F=[[0,0] for _ in range(N)]
    for a in range(N):
        for b in range(a+1,N):
            r=dist(X,a,b); e=[(X[a][k]-X[b][k])/r for k in range(2)]; f=[-Phi(a,b)*Wp(r)*e[k] for k in range(2)]
            for k in range(2): F[a][k]+=f[k]; F[b][k]-=f[k]
    return F
def numforce(kind,d=1e-6):
    G=[[0,0] for _ in range(N)]
    for a in range(N):
        for k in range(2):
            Xp=[x[:] for x in X]; Xm=[x[:] for x in X]; Xp[a][k]+=d; Xm[a][k]-=d
            G[a][k]=-(U(Xp,S,kind)-U(Xm,S,kind))/(2*d)
    return G
def relerr(F,G): return max(abs(F[a][k]-G[a][k]) for a in range(N) for k in range(2))/max(abs(G[a][k]) for a in range(N) for k in range(2))
for kind in ['mass','entropic','direct','implicit','mixed']:
    print(f'{kind:9s} pair force vs -dU/dx rel.err {relerr(force(X,S,kind),numforce(kind)):.1e}')
print(f'printed (37b) rel.err {relerr(force(X,S,"entropic",printed37b=True),numforce("entropic")):.2f}  (corrected S_b^2 form is the line above)')
for kind in ['mass','entropic','direct','implicit','mixed']:
    Wm,rho,s,V=state(X,S,kind); T=[T_(rho[a],s[a]) for a in range(N)]; p=[p_(rho[a],s[a]) for a in range(N)]
    e1=e2=0
    for a in range(N):
        Sp=S[:]; Sm=S[:]; Sp[a]+=1e-6; Sm[a]-=1e-6; th=(U(X,Sp,kind)-U(X,Sm,kind))/2e-6
        pred={'entropic':T[a]-p[a]/s[a]+sum(p[c]*V[c]/s[c]*Wm[c][a] for c in range(N)),
              'mixed':sum(V[c]*T[c]*Wm[c][a] for c in range(N))}.get(kind,T[a])
        e1=max(e1,abs(th-T[a])/T[a]); e2=max(e2,abs(th-pred)/T[a])
    print(f'{kind:9s} max|dE/dS_a - T_a|/T {e1:.1e}   max|dE/dS_a - theta_a|/T {e2:.1e}')
# dissipation / hyperbolic balances (mass volume, static particles)
Wm,rho,s,V=state(X,S,'mass'); T=[T_(rho[a],s[a]) for a in range(N)]
pairs=[(a,b,Wp(dist(X,a,b)),dist(X,a,b),[(X[a][k]-X[b][k])/dist(X,a,b) for k in range(2)]) for a in range(N) for b in range(N) if a!=b]
alpha,tau,mu,n=0.1,0.3,0.7,2
w=[[random.uniform(-1,1) for k in range(2)] for _ in range(N)]; Ew=[[alpha*V[a]*w[a][k] for k in range(2)] for a in range(N)]
Sd=[0]*N; wd=[[0,0] for _ in range(N)]
for a,b,wp,r,e in pairs:
    Sd[a]+=-V[a]*V[b]*sum((Ew[a][k]/V[a]+Ew[b][k]/V[b])*wp*e[k] for k in range(2))   # (68a)
    for k in range(2): wd[a][k]+=V[b]*(T[a]-T[b])*wp*e[k]                            # (68b)
print('(68) sum dS/dt %.1e  dE/dt %.1e'%(sum(Sd),sum(T[a]*Sd[a] for a in range(N))+sum(Ew[a][k]*wd[a][k] for a in range(N) for k in range(2))))
G=[[0,0] for _ in range(N)]
for a,b,wp,r,e in pairs:
    for k in range(2): G[a][k]+=-V[b]*(T[a]-T[b])*wp*e[k]                              # G0_a(T)
J=[[-tau*G[a][k] for k in range(2)] for a in range(N)]                                 # (71): E_w = q/T
Sd2=[0]*N
for a,b,wp,r,e in pairs: Sd2[a]+=-V[a]*V[b]*sum((J[a][k]/V[a]+J[b][k]/V[b])*wp*e[k] for k in range(2))
for a in range(N): Sd2[a]+=tau/T[a]*(G[a][0]**2+G[a][1]**2)                          # corrected (72)
print('(72)-(74) corrected: sum T dS/dt %.1e   sum dS/dt %.4f = sum tau|G(T)|^2/T %.4f'%(sum(T[a]*Sd2[a] for a in range(N)),sum(Sd2),sum(tau/T[a]*(G[a][0]**2+G[a][1]**2) for a in range(N))))
v=[[random.uniform(-1,1) for k in range(2)] for _ in range(N)]; Pk=0; Sv=[0]*N
for a,b,wp,r,e in pairs:
    vab=sum((v[a][k]-v[b][k])*e[k] for k in range(2))
    Pk+=sum(v[a][k]*2*(n+2)*mu*V[a]*V[b]*vab*wp/r*e[k] for k in range(2))             # (60),(61)
    Sv[a]+=-(n+2)*mu*V[a]*V[b]*vab**2*wp/r/T[a]                                       # (63) with W'
print('(60)/(63 with W\') dEkin/dt %.4f  sum T dS/dt %.4f  min dS_a/dt %.3f'%(Pk,sum(T[a]*Sv[a] for a in range(N)),min(Sv)))
Epi=[[random.uniform(-1,1) for k in range(2)] for _ in range(N)]
print('(77d) S-form: sum dS/dt from pi coupling = %.3f (not 0)'%sum(S[a]/rho[a]*m[b]*sum((Epi[a][k]-Epi[b][k])*wp*e[k] for k in range(2)) for a,b,wp,r,e in pairs))
import sympy as sp
rho,s,g,c,c0,r0,p0,sig=sp.symbols('rho s gamma c_V c_0 rho_0 p_0 sigma',positive=True)
e2=rho*(c0**2/(g*(g-1))*(rho/r0)**(g-1)*sp.exp(s/(c*rho))+(r0*c0**2-g*p0)/(g*rho))   # (90)
mu2=sp.diff(e2,rho)
printed=c0**2/(g-1)*(rho/r0)**(g-1)*sp.exp(s/(rho*c))-rho*c0**2/(g*(g-1))*(rho/r0)**(g-1)*s/(rho**2*c)
print('(91c) printed - true mu:',sp.simplify(printed-mu2))
