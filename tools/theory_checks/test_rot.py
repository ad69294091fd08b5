import math
from la import *
from plate import *
gp3=[(2/3,1/6,1/6),(1/6,2/3,1/6),(1/6,1/6,2/3)]
def K9(xy,Bf,Db):
    b,c,A2=geom(xy); K=mat(9,9)
    for L in gp3:
        B=Bf(xy,L); DB=mm(Db,B)
        for a in range(9):
            for bb in range(9):
                K[a][bb]+=A2/2/3*sum(B[r][a]*DB[r][bb] for r in range(3))
    return K,A2/2
def lam_max(M,K):
    # max eig of M^-1 K (M diag) by power iteration on symmetric M^-1/2 K M^-1/2
    n=len(K); s=[1/math.sqrt(m) for m in M]
    S=[[s[i]*K[i][j]*s[j] for j in range(n)] for i in range(n)]
    v=[1.0+0.1*i for i in range(n)]
    for _ in range(3000):
        w=mv(S,v); nn=norm(w); v=[x/nn for x in w]
    return dot(v,mv(S,v))
def main():
    E,nu,rho=1.0,0.3,1.0; c=math.sqrt(E/(rho*(1-nu*nu)))
    xy=[[0,0],[1,0],[0.5,math.sqrt(3)/2]]
    for name,Bf in (('DKT',B9_dkt),('BCIZ',B9_bciz)):
      for h in (0.01,0.05,0.2,0.5):
        Dbs=E*h**3/(12*(1-nu*nu)); Db=[[Dbs,nu*Dbs,0],[nu*Dbs,Dbs,0],[0,0,Dbs*(1-nu)/2]]
        K,A=K9(xy,Bf,Db)
        m=rho*h*A/3
        # rigid tributary inertia: mass m spread over whole triangle about node (average of in-plane axes)
        p=[1,0];q=[0.5,math.sqrt(3)/2]
        trS=A/12*(2*dot(p,p)+2*dot(q,q)+2*dot(p,q))
        res=[]
        for lab,I in (('phys h2/12',m*h*h/12),('KBL A/8+h2/12',m*(A/8+h*h/12)),('rigid-trib',rho*h/3*0.5*trS+rho*h**3*A/36)):
            M=[m,I,I]*3
            w2=lam_max(M,K)
            res.append('%s: dt_b/dt_m=%.2f'%(lab, (2/math.sqrt(w2))/ (0.827*(2*A/1.0)/c)))
        print(name,'h/L=%.2f'%h,' | '.join(res))

if __name__ == '__main__':
    main()
