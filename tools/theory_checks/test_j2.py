import math, random
from la import *
E,nu=200e3,0.3; G=E/(2*(1+nu)); K=E/(3*(1-2*nu))
sy,Hi,Hk=250.0,1000.0,800.0
C=[[E/(1-nu*nu),E*nu/(1-nu*nu),0],[E*nu/(1-nu*nu),E/(1-nu*nu),0],[0,0,G]]
P=[[2/3,-1/3,0],[-1/3,2/3,0],[0,0,2]]
kap=lambda a: sy+Hi*a; dkap=lambda a: Hi
def ps_return(sig,b,alpha,de):
    st=add(sig,mv(C,de)); xt=add(st,b,-1)
    ftr=0.5*dot(xt,mv(P,xt))-kap(alpha)**2/3
    if ftr<=0: return st,b,alpha,0.0
    A1=(xt[0]+xt[1])**2/6; A2=0.5*(xt[1]-xt[0])**2+2*xt[2]**2
    a1=E/(3*(1-nu))+2/3*Hk; a2=2*G+2/3*Hk
    dg=0.0
    for it in range(50):
        fb2=A1/(1+a1*dg)**2+A2/(1+a2*dg)**2; fb=math.sqrt(fb2)
        dfb2=-2*A1*a1/(1+a1*dg)**3-2*A2*a2/(1+a2*dg)**3
        al=alpha+math.sqrt(2/3)*dg*fb
        F=0.5*fb2-kap(al)**2/3
        dal=math.sqrt(2/3)*(fb+dg*dfb2/(2*fb))
        dF=0.5*dfb2-2/3*kap(al)*dkap(al)*dal
        dg-=F/dF
        if abs(F)<1e-12*kap(al)**2: break
    s=(xt[0]+xt[1])/(1+a1*dg); d=(xt[1]-xt[0])/(1+a2*dg)
    xi=[(s-d)/2,(s+d)/2,xt[2]/(1+a2*dg)]
    fb=math.sqrt(dot(xi,mv(P,xi)))
    bn=add(b,scal(2/3*Hk*dg,xi)); sn=add(bn,xi)
    # direct-solve cross check
    Mx=[[(1+2/3*Hk*dg)*(1 if i==j else 0)+dg*sum(C[i][k]*P[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    xi2=solve(Mx,xt)
    err=max(abs(x-y) for x,y in zip(xi,xi2))
    return sn,bn,alpha+math.sqrt(2/3)*dg*fb,err
# 3D reference: radial return with nested sigma33=0 via secant on de33
def dev(t): m=(t[0][0]+t[1][1]+t[2][2])/3; return [[t[i][j]-(m if i==j else 0) for j in range(3)] for i in range(3)]
def ddot(a,b): return sum(a[i][j]*b[i][j] for i in range(3) for j in range(3))
def r3d(sig,beta,alpha,de):
    tr_=de[0][0]+de[1][1]+de[2][2]
    st=[[sig[i][j]+2*G*de[i][j]+(K-2*G/3)*tr_*(1 if i==j else 0) for j in range(3)] for i in range(3)]
    xi=[[dev(st)[i][j]-beta[i][j] for j in range(3)] for i in range(3)]
    nx=math.sqrt(ddot(xi,xi)); f=nx-math.sqrt(2/3)*kap(alpha)
    if f<=0: return st,beta,alpha
    dg=f/(2*G+2/3*(Hi+Hk))  # linear hardening closed form
    n=[[xi[i][j]/nx for j in range(3)] for i in range(3)]
    sn=[[st[i][j]-2*G*dg*n[i][j] for j in range(3)] for i in range(3)]
    bn=[[beta[i][j]+2/3*Hk*dg*n[i][j] for j in range(3)] for i in range(3)]
    return sn,bn,alpha+math.sqrt(2/3)*dg
def r3d_ps(sig,beta,alpha,dein):
    def res(e33):
        de=[[dein[0],dein[2]/2,0],[dein[2]/2,dein[1],0],[0,0,e33]]
        return r3d(sig,beta,alpha,de)
    a,bq=-0.01,0.01
    fa=res(a)[0][2][2]; fb=res(bq)[0][2][2]
    for it in range(200):
        m=(a+bq)/2; fm=res(m)[0][2][2]
        if fa*fm<=0: bq,fb=m,fm
        else: a,fa=m,fm
    return res((a+bq)/2)
def main():
    random.seed(0)
    sig=[0,0,0]; b=[0,0,0]; al=0.0
    S=[[0]*3 for _ in range(3)]; B=[[0]*3 for _ in range(3)]; A=0.0
    maxerr=0; maxd=0
    for step in range(60):
        de=[random.uniform(-1,1)*4e-4+ (8e-4 if step<20 else -6e-4), random.uniform(-1,1)*4e-4, random.uniform(-1,1)*6e-4]
        sig,b,al,e=ps_return(sig,b,al,de); maxerr=max(maxerr,e)
        S,B,A=r3d_ps(S,B,A,de)
        maxd=max(maxd,abs(sig[0]-S[0][0]),abs(sig[1]-S[1][1]),abs(sig[2]-S[0][1]))
        # consistency check
    print('eigen-vs-direct xi err',maxerr,' max |sigma_ps - sigma_3D(s33=0)| =',maxd,' alpha',al,A)
    # back-stress relation b = [2b11+b22, 2b22+b11, b12]
    print('b(ps)=',[round(x,6) for x in b],' from 3D beta:',[round(2*B[0][0]+B[1][1],6),round(2*B[1][1]+B[0][0],6),round(B[0][1],6)])

if __name__ == '__main__':
    main()
